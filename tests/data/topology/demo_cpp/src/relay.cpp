// A component registered with an executable; its header is followed from here.
#include "demo_cpp/relay.hpp"

#include "rclcpp_components/register_node_macro.hpp"

namespace demo_cpp
{

// The members below are declared in the header: this file alone cannot tell what they are.
Relay::Relay(const rclcpp::NodeOptions & options)
: Node("relay", options),  // expect-node-name: relay
  feedback_(this, "feedback"),
  static_frames_(*this)
{
  auto out_topic = declare_parameter<std::string>("out_topic", "/cmd_vel");
  // Twist is an alias of the header: this file alone does not type it, the executable does
  out_ = create_publisher<Twist>(out_topic, rclcpp::QoS(10).reliable());  // expect: publisher /cmd_vel ? param=out_topic
  setup();
  // TwistSubscriber is the header's typedef of a message_filters subscriber
  limits_.reset(new TwistSubscriber(this, "limits"));
}

}  // namespace demo_cpp

RCLCPP_COMPONENTS_REGISTER_NODE(demo_cpp::Relay)
