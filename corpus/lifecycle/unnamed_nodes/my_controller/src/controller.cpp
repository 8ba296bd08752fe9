#include <rclcpp_lifecycle/lifecycle_node.hpp>

class Controller : public rclcpp_lifecycle::LifecycleNode
{
public:
  Controller() : rclcpp_lifecycle::LifecycleNode("controller_server") {}
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Controller>()->get_node_base_interface());
  return 0;
}
