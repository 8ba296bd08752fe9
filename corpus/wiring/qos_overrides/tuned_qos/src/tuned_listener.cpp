#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "sensor_msgs/msg/laser_scan.hpp"

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("tuned_listener");
  // best effort by default; the id makes its parameters qos_overrides.<topic>.subscription_fast.*
  rclcpp::SubscriptionOptions options;
  options.qos_overriding_options = rclcpp::QosOverridingOptions(
    {rclcpp::QosPolicyKind::Reliability, rclcpp::QosPolicyKind::Depth}, nullptr, "fast");
  auto scan = node->create_subscription<sensor_msgs::msg::LaserScan>(
    "scan", rclcpp::SensorDataQoS(), [](sensor_msgs::msg::LaserScan::ConstSharedPtr) {},
    options);
  rclcpp::spin(node);
  rclcpp::shutdown();
  return 0;
}
