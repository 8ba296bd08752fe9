#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "sensor_msgs/msg/battery_state.hpp"

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("battery_monitor");
  auto battery = node->create_publisher<sensor_msgs::msg::BatteryState>("/fleet/battery", 10);
  rclcpp::spin(node);
  rclcpp::shutdown();
  return 0;
}
