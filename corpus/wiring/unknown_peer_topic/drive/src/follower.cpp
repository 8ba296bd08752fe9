// Follows a dock's marker: velocity commands of its own, straight to cmd_vel.
#include <memory>

#include "geometry_msgs/msg/twist.hpp"
#include "rclcpp/rclcpp.hpp"

class Follower : public rclcpp::Node
{
public:
  Follower()
  : Node("follower")
  {
    publisher_ = create_publisher<geometry_msgs::msg::Twist>("cmd_vel", 10);
  }

private:
  rclcpp::PublisherBase::SharedPtr publisher_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Follower>());
  rclcpp::shutdown();
  return 0;
}
