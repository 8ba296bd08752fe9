// Sends docking goals.
#include <memory>

#include "nav2_msgs/action/dock_robot.hpp"
#include "rclcpp/rclcpp.hpp"
#include "rclcpp_action/rclcpp_action.hpp"

class DockClient : public rclcpp::Node
{
public:
  DockClient()
  : Node("dock_client")
  {
    client_ = rclcpp_action::create_client<nav2_msgs::action::DockRobot>(this, "dock_robot");
  }

private:
  rclcpp_action::Client<nav2_msgs::action::DockRobot>::SharedPtr client_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<DockClient>());
  rclcpp::shutdown();
  return 0;
}
