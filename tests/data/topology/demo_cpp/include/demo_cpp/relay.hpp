// A component whose endpoints are created in its header.
#pragma once

#include <string>

#include "rclcpp/rclcpp.hpp"
#include "geometry_msgs/msg/twist.hpp"

namespace demo_cpp
{

using Twist = geometry_msgs::msg::Twist;

class Relay : public rclcpp::Node
{
public:
  explicit Relay(const rclcpp::NodeOptions & options);

private:
  void setup()
  {
    in_ = create_subscription<Twist>("cmd_vel_in", 10, [this](Twist::ConstSharedPtr msg) {  // expect: subscription cmd_vel_in geometry_msgs/msg/Twist
        out_->publish(*msg);
      });
  }

  rclcpp::Subscription<Twist>::SharedPtr in_;
  rclcpp::Publisher<Twist>::SharedPtr out_;
};

}  // namespace demo_cpp
