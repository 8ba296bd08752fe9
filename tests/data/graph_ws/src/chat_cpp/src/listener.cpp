// Hears the talker on the same relative name.
#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"

int main(int argc, char * argv[])
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("listener");
  auto heard = node->create_subscription<std_msgs::msg::String>(
    "chatter", 10, [](std_msgs::msg::String::ConstSharedPtr) {});
  rclcpp::spin(node);
  rclcpp::shutdown();
  return 0;
}
