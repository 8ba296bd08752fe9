// The base: takes stamped velocity commands.
#include <memory>

#include "geometry_msgs/msg/twist.hpp"
#include "geometry_msgs/msg/twist_stamped.hpp"
#include "rclcpp/rclcpp.hpp"

class BaseController : public rclcpp::Node
{
public:
  BaseController()
  : Node("base_controller")
  {
    subscription_ = create_subscription<geometry_msgs::msg::TwistStamped>(
      "cmd_vel", 10, [](geometry_msgs::msg::TwistStamped::ConstSharedPtr) {});
  }

private:
  rclcpp::PublisherBase::SharedPtr publisher_;
  rclcpp::SubscriptionBase::SharedPtr subscription_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<BaseController>());
  rclcpp::shutdown();
  return 0;
}
