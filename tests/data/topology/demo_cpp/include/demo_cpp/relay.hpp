// A component whose endpoints are created in its header.
#pragma once

#include <string>

#include "rclcpp/rclcpp.hpp"
#include "geometry_msgs/msg/twist.hpp"
#include "message_filters/subscriber.h"
#include "tf2_ros/static_transform_broadcaster.h"

namespace demo_cpp
{

using Twist = geometry_msgs::msg::Twist;
typedef message_filters::Subscriber<Twist> TwistSubscriber;

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
  // built in relay.cpp's initialiser list: typed from here when the executable is read
  message_filters::Subscriber<Twist> feedback_;
  tf2_ros::StaticTransformBroadcaster static_frames_;
  std::shared_ptr<TwistSubscriber> limits_;
};

}  // namespace demo_cpp
