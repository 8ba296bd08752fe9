// The classic talker: a literal topic name, a queue depth.
#include <chrono>
#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"

using namespace std::chrono_literals;

class Talker : public rclcpp::Node
{
public:
  Talker()
  : Node("talker")  // expect-node-name: talker
  {
    publisher_ = this->create_publisher<std_msgs::msg::String>("chatter", 10);  // expect: publisher chatter std_msgs/msg/String
    timer_ = create_wall_timer(500ms, [this]() {publish();});
  }

private:
  void publish()
  {
    auto message = std_msgs::msg::String();
    message.data = "hello";
    publisher_->publish(message);
  }

  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr publisher_;
  rclcpp::TimerBase::SharedPtr timer_;
};

int main(int argc, char * argv[])
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Talker>());
  rclcpp::shutdown();
  return 0;
}
