// The name comes from the command line: not known before launch.
#include <memory>
#include <string>

#include "rclcpp/rclcpp.hpp"

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  std::string name = argc > 1 ? argv[1] : "worker";
  rclcpp::spin(std::make_shared<rclcpp::Node>(name));
  rclcpp::shutdown();
  return 0;
}
