namespace demo_controllers
{
void FogLayer::onInitialize()
{
  auto node = node_.lock();
  fog_sub_ = node->create_subscription<std_msgs::msg::Float64>("fog", 1, on_fog);  // expect: subscription fog std_msgs/msg/Float64
}
}  // namespace demo_controllers
