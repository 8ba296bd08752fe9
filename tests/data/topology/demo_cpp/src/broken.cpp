// Code that does not compile here: an unknown macro, a missing semicolon, an unclosed brace.
#include "rclcpp/rclcpp.hpp"

VENDOR_EXPORT_MACRO(class) Broken : public rclcpp::Node
{
public:
  Broken() : Node("broken")  // the class head is lost to the macro: no node name
  {
    pub_ = create_publisher<std_msgs::msg::Bool>("ready", 1)  // expect: publisher ready std_msgs/msg/Bool
    int x = VENDOR_MAGIC(;
    sub_ = create_subscription<std_msgs::msg::Empty>("trigger", 1, cb_);  // expect: subscription trigger std_msgs/msg/Empty
