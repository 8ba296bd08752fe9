// Asks for a battery reset, expecting a Trigger service (it wants the success flag).
#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "std_srvs/srv/trigger.hpp"

class BatteryClient : public rclcpp::Node
{
public:
  BatteryClient()
  : Node("battery_client")
  {
    client_ = create_client<std_srvs::srv::Trigger>("reset_battery");
  }

private:
  rclcpp::Client<std_srvs::srv::Trigger>::SharedPtr client_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<BatteryClient>());
  rclcpp::shutdown();
  return 0;
}
