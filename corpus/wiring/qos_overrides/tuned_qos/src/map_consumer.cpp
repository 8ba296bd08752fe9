#include <memory>

#include "nav_msgs/msg/occupancy_grid.hpp"
#include "rclcpp/rclcpp.hpp"

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("map_consumer");
  auto map = node->create_subscription<nav_msgs::msg::OccupancyGrid>(
    "map", rclcpp::QoS(1).transient_local(),
    [](nav_msgs::msg::OccupancyGrid::ConstSharedPtr) {});
  rclcpp::spin(node);
  rclcpp::shutdown();
  return 0;
}
