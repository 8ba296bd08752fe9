// Actions and services, created on a node pointer held by a plain class.
#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "rclcpp_action/rclcpp_action.hpp"
#include "example_interfaces/action/fibonacci.hpp"
#include "example_interfaces/srv/add_two_ints.hpp"

class FibonacciServer
{
public:
  using Fibonacci = example_interfaces::action::Fibonacci;
  using GoalHandle = rclcpp_action::ServerGoalHandle<Fibonacci>;

  explicit FibonacciServer(rclcpp::Node::SharedPtr node)
  : node_(node)
  {
    server_ = rclcpp_action::create_server<Fibonacci>(  // expect: action_server fibonacci example_interfaces/action/Fibonacci
      node_, "fibonacci",
      [](const rclcpp_action::GoalUUID &, std::shared_ptr<const Fibonacci::Goal>) {
        return rclcpp_action::GoalResponse::ACCEPT_AND_EXECUTE;
      },
      [](std::shared_ptr<GoalHandle>) {return rclcpp_action::CancelResponse::ACCEPT;},
      [](std::shared_ptr<GoalHandle>) {});
    upstream_ = rclcpp_action::create_client<Fibonacci>(node_, "/upstream/fibonacci");  // expect: action_client /upstream/fibonacci example_interfaces/action/Fibonacci
    adder_ = node_->create_service<example_interfaces::srv::AddTwoInts>(  // expect: service add_two_ints example_interfaces/srv/AddTwoInts
      "add_two_ints",
      [](const std::shared_ptr<example_interfaces::srv::AddTwoInts::Request>,
      std::shared_ptr<example_interfaces::srv::AddTwoInts::Response>) {});
  }

private:
  rclcpp::Node::SharedPtr node_;
  rclcpp_action::Server<Fibonacci>::SharedPtr server_;
  rclcpp_action::Client<Fibonacci>::SharedPtr upstream_;
  rclcpp::Service<example_interfaces::srv::AddTwoInts>::SharedPtr adder_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = rclcpp::Node::make_shared("fibonacci_server");  // expect-node-name: fibonacci_server
  FibonacciServer server(node);
  rclcpp::spin(node);
  return 0;
}
