#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "sensor_msgs/msg/laser_scan.hpp"

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("scan_consumer");
  // the default profile, reliable, and no overrides
  auto scan = node->create_subscription<sensor_msgs::msg::LaserScan>(
    "scan", 10, [](sensor_msgs::msg::LaserScan::ConstSharedPtr) {});
  rclcpp::spin(node);
  rclcpp::shutdown();
  return 0;
}
