// A controller: its node is the controller manager's child, named by the controller's
// configuration, so every name here is private to it.
namespace demo_controllers
{
controller_interface::CallbackReturn SpeedController::on_configure(const rclcpp_lifecycle::State &)
{
  command_sub_ = get_node()->create_subscription<std_msgs::msg::Float64>(  // expect: subscription ~/speed std_msgs/msg/Float64
    "~/speed", rclcpp::SystemDefaultsQoS(), on_command);
  return controller_interface::CallbackReturn::SUCCESS;
}
}  // namespace demo_controllers
