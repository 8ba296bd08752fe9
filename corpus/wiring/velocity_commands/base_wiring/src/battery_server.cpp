// Resets the battery estimate: std_srvs/Empty.
#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "std_srvs/srv/empty.hpp"

class BatteryServer : public rclcpp::Node
{
public:
  BatteryServer()
  : Node("battery_server")
  {
    service_ = create_service<std_srvs::srv::Empty>(
      "reset_battery",
      [](const std::shared_ptr<std_srvs::srv::Empty::Request>,
      std::shared_ptr<std_srvs::srv::Empty::Response>) {});
  }

private:
  rclcpp::Service<std_srvs::srv::Empty>::SharedPtr service_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<BatteryServer>());
  rclcpp::shutdown();
  return 0;
}
