#include <memory>

#include "rclcpp/rclcpp.hpp"

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto options = rclcpp::NodeOptions()
    .allow_undeclared_parameters(true)
    .automatically_declare_parameters_from_overrides(true);
  auto node = std::make_shared<rclcpp::Node>("flexible", options);
  node->declare_parameter("rate", 10.0);
  rclcpp::spin(node);
  rclcpp::shutdown();
  return 0;
}
