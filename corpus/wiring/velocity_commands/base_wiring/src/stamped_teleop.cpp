// Keyboard teleop sending stamped commands (what Jazzy's diff_drive_controller expects).
#include <memory>

#include "geometry_msgs/msg/twist.hpp"
#include "geometry_msgs/msg/twist_stamped.hpp"
#include "rclcpp/rclcpp.hpp"

class StampedTeleop : public rclcpp::Node
{
public:
  StampedTeleop()
  : Node("stamped_teleop")
  {
    publisher_ = create_publisher<geometry_msgs::msg::TwistStamped>("cmd_vel", 10);
  }

private:
  rclcpp::PublisherBase::SharedPtr publisher_;
  rclcpp::SubscriptionBase::SharedPtr subscription_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<StampedTeleop>());
  rclcpp::shutdown();
  return 0;
}
