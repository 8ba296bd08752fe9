// A twist_mux: one input per source, one output.
#include <memory>

#include "geometry_msgs/msg/twist.hpp"
#include "rclcpp/rclcpp.hpp"

class CmdMux : public rclcpp::Node
{
public:
  CmdMux()
  : Node("cmd_mux")
  {
    output_ = create_publisher<geometry_msgs::msg::Twist>("cmd_vel", 10);
    teleop_ = create_subscription<geometry_msgs::msg::Twist>(
      "cmd_vel_teleop", 10, [this](geometry_msgs::msg::Twist::ConstSharedPtr msg) {output_->publish(*msg);});
    follow_ = create_subscription<geometry_msgs::msg::Twist>(
      "cmd_vel_follow", 10, [this](geometry_msgs::msg::Twist::ConstSharedPtr msg) {output_->publish(*msg);});
  }

private:
  rclcpp::Publisher<geometry_msgs::msg::Twist>::SharedPtr output_;
  rclcpp::Subscription<geometry_msgs::msg::Twist>::SharedPtr teleop_;
  rclcpp::Subscription<geometry_msgs::msg::Twist>::SharedPtr follow_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<CmdMux>());
  rclcpp::shutdown();
  return 0;
}
