// A component whose constructor names it: loaded without name=, it is /relay.
#include "rclcpp/rclcpp.hpp"
#include "rclcpp_components/register_node_macro.hpp"
#include "std_msgs/msg/string.hpp"

namespace chatter_cpp
{

class Relay : public rclcpp::Node
{
public:
  explicit Relay(const rclcpp::NodeOptions & options)
  : Node("relay", options)
  {
    publisher_ = create_publisher<std_msgs::msg::String>("relayed", 10);
  }

private:
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr publisher_;
};

}  // namespace chatter_cpp

RCLCPP_COMPONENTS_REGISTER_NODE(chatter_cpp::Relay)
