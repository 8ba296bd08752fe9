// Serves docking goals.
#include <memory>

#include "nav2_msgs/action/dock_robot.hpp"
#include "rclcpp/rclcpp.hpp"
#include "rclcpp_action/rclcpp_action.hpp"

using DockRobot = nav2_msgs::action::DockRobot;
using GoalHandle = rclcpp_action::ServerGoalHandle<DockRobot>;

class DockServer : public rclcpp::Node
{
public:
  DockServer()
  : Node("dock_server")
  {
    server_ = rclcpp_action::create_server<DockRobot>(
      this, "dock_robot",
      [](const rclcpp_action::GoalUUID &, std::shared_ptr<const DockRobot::Goal>) {
        return rclcpp_action::GoalResponse::ACCEPT_AND_EXECUTE;
      },
      [](const std::shared_ptr<GoalHandle>) {return rclcpp_action::CancelResponse::ACCEPT;},
      [](const std::shared_ptr<GoalHandle>) {});
  }

private:
  rclcpp_action::Server<DockRobot>::SharedPtr server_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<DockServer>());
  rclcpp::shutdown();
  return 0;
}
