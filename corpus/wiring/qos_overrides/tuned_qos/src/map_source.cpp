#include <memory>

#include "nav_msgs/msg/occupancy_grid.hpp"
#include "rclcpp/rclcpp.hpp"

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("map_source");
  // volatile; the default policies (history, depth, reliability) leave durability fixed
  rclcpp::PublisherOptions options;
  options.qos_overriding_options = rclcpp::QosOverridingOptions::with_default_policies();
  auto map = node->create_publisher<nav_msgs::msg::OccupancyGrid>(
    "map", rclcpp::QoS(1), options);
  rclcpp::spin(node);
  rclcpp::shutdown();
  return 0;
}
