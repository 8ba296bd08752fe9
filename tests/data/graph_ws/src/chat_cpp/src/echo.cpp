// A component that repeats what it hears, and answers a reset request.
#include "rclcpp/rclcpp.hpp"
#include "rclcpp_components/register_node_macro.hpp"
#include "std_msgs/msg/string.hpp"
#include "std_srvs/srv/empty.hpp"

namespace chat_cpp
{

class Echo : public rclcpp::Node
{
public:
  explicit Echo(const rclcpp::NodeOptions & options)
  : Node("echo", options)
  {
    out_ = create_publisher<std_msgs::msg::String>("out", 10);
    in_ = create_subscription<std_msgs::msg::String>(
      "in", 10, [this](std_msgs::msg::String::ConstSharedPtr msg) {out_->publish(*msg);});
    reset_ = create_service<std_srvs::srv::Empty>(
      "~/reset", [](const std::shared_ptr<std_srvs::srv::Empty::Request>,
      std::shared_ptr<std_srvs::srv::Empty::Response>) {});
  }

private:
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr out_;
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr in_;
  rclcpp::Service<std_srvs::srv::Empty>::SharedPtr reset_;
};

}  // namespace chat_cpp

RCLCPP_COMPONENTS_REGISTER_NODE(chat_cpp::Echo)
