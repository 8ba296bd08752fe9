// The node is called "talker" by its code: launched without name=, it runs as /talker.
#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("talker");
  auto publisher = node->create_publisher<std_msgs::msg::String>("chatter", 10);
  rclcpp::spin(node);
  rclcpp::shutdown();
  return 0;
}
