namespace demo_controllers
{
controller_interface::CallbackReturn LevelBroadcaster::on_configure(const rclcpp_lifecycle::State &)
{
  level_pub_ = get_node()->create_publisher<std_msgs::msg::Float64>("~/level", 10);  // expect: publisher ~/level std_msgs/msg/Float64
  return controller_interface::CallbackReturn::SUCCESS;
}
}  // namespace demo_controllers
