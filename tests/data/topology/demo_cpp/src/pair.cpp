// Two components in one library: each keeps its own endpoints.
#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/int32.hpp"

namespace demo_cpp
{

class Ping : public rclcpp::Node
{
public:
  explicit Ping(const rclcpp::NodeOptions & options)
  : Node("ping", options)  // expect-node-name: ping
  {
    pub_ = create_publisher<std_msgs::msg::Int32>("ping", 1);  // expect: publisher ping std_msgs/msg/Int32
  }

private:
  rclcpp::Publisher<std_msgs::msg::Int32>::SharedPtr pub_;
};

class Pong : public rclcpp::Node
{
public:
  explicit Pong(const rclcpp::NodeOptions & options);

private:
  rclcpp::Subscription<std_msgs::msg::Int32>::SharedPtr sub_;
};

Pong::Pong(const rclcpp::NodeOptions & options)
: Node("pong", options)  // expect-node-name: pong
{
  sub_ = create_subscription<std_msgs::msg::Int32>(  // expect: subscription ping std_msgs/msg/Int32
    "ping", 1, [](std_msgs::msg::Int32::ConstSharedPtr) {});
}

}  // namespace demo_cpp

#include "rclcpp_components/register_node_macro.hpp"
RCLCPP_COMPONENTS_REGISTER_NODE(demo_cpp::Ping)
RCLCPP_COMPONENTS_REGISTER_NODE(demo_cpp::Pong)
