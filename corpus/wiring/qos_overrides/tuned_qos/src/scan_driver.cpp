#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "sensor_msgs/msg/laser_scan.hpp"

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("scan_driver");
  // best effort unless the launch says otherwise: only reliability is open to overrides
  rclcpp::PublisherOptions options;
  options.qos_overriding_options = rclcpp::QosOverridingOptions({
    rclcpp::QosPolicyKind::Reliability,
  });
  auto scan = node->create_publisher<sensor_msgs::msg::LaserScan>(
    "scan", rclcpp::SensorDataQoS(), options);
  rclcpp::spin(node);
  rclcpp::shutdown();
  return 0;
}
