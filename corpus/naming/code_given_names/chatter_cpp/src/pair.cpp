// One process, two nodes with names of their own: which one a launch line stands for is
// not a fact.
#include <memory>

#include "rclcpp/rclcpp.hpp"

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto ping = std::make_shared<rclcpp::Node>("ping");
  auto pong = std::make_shared<rclcpp::Node>("pong");
  rclcpp::executors::SingleThreadedExecutor executor;
  executor.add_node(ping);
  executor.add_node(pong);
  executor.spin();
  rclcpp::shutdown();
  return 0;
}
