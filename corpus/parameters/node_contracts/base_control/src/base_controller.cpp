#include <memory>
#include <string>

#include "geometry_msgs/msg/twist.hpp"
#include "rclcpp/rclcpp.hpp"

class BaseController : public rclcpp::Node
{
public:
  BaseController()
  : Node("base_controller")
  {
    max_velocity_x_ = declare_parameter("max_velocity_x", 0.5);
    max_rotation_ = declare_parameter<double>("max_rotation", 1.0);
    wheel_count_ = declare_parameter("wheel_count", 4);
    frame_ = declare_parameter("base_frame", std::string("base_link"));
    port_ = declare_parameter<std::string>("port");  // no default: must be given
    rcl_interfaces::msg::ParameterDescriptor loose;
    loose.dynamic_typing = true;
    declare_parameter("gain", 1.0, loose);  // any type is accepted
    cmd_ = create_subscription<geometry_msgs::msg::Twist>(
      "cmd_vel", 10, [](geometry_msgs::msg::Twist::ConstSharedPtr) {});
  }

private:
  double max_velocity_x_;
  double max_rotation_;
  int64_t wheel_count_;
  std::string frame_;
  std::string port_;
  rclcpp::Subscription<geometry_msgs::msg::Twist>::SharedPtr cmd_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<BaseController>());
  rclcpp::shutdown();
  return 0;
}
