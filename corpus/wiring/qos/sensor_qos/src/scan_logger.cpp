#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "sensor_msgs/msg/laser_scan.hpp"

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("scan_logger");
  auto qos = rclcpp::QoS(rclcpp::KeepLast(5));
  qos.best_effort();  // takes reliable and best-effort publishers alike
  auto scan = node->create_subscription<sensor_msgs::msg::LaserScan>(
    "scan", qos, [](sensor_msgs::msg::LaserScan::ConstSharedPtr) {});
  rclcpp::spin(node);
  rclcpp::shutdown();
  return 0;
}
