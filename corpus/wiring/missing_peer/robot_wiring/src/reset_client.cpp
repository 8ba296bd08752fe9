// Resets the odometry at start-up: calls "reset", which the matcher serves as ~/reset.
#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "std_srvs/srv/trigger.hpp"

class ResetClient : public rclcpp::Node
{
public:
  ResetClient()
  : Node("reset_client")
  {
    client_ = create_client<std_srvs::srv::Trigger>("reset");
  }

private:
  rclcpp::Client<std_srvs::srv::Trigger>::SharedPtr client_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<ResetClient>());
  rclcpp::shutdown();
  return 0;
}
