// Names from parameters, from members, and the traps that must stay unknown.
#include <string>

#include "rclcpp/rclcpp.hpp"
#include "sensor_msgs/msg/laser_scan.hpp"
#include "std_srvs/srv/trigger.hpp"

using sensor_msgs::msg::LaserScan;

namespace demo_cpp
{

std::string topic_for(const std::string & base);

class ScanFilter : public rclcpp::Node
{
public:
  explicit ScanFilter(const rclcpp::NodeOptions & options)
  : rclcpp::Node("scan_filter", options), diagnostics_topic_("~/diagnostics")  // expect-node-name: scan_filter
  {
    declare_parameter("input_topic", "scan");
    std::string input = get_parameter("input_topic").as_string();
    auto output = this->declare_parameter<std::string>("output_topic", "scan_filtered");
    this->declare_parameter("status_topic", std::string("status"));
    this->get_parameter("status_topic", status_topic_);
    const std::string prefix = get_namespace();
    std::string built = prefix + "/scan_raw";
    std::string twice = "a";
    if (options.use_intra_process_comms()) {
      twice = "b";
    }
    const std::string fixed = "/emergency_stop";

    sub_ = create_subscription<LaserScan>(input, rclcpp::SensorDataQoS(), cb_);  // expect: subscription scan sensor_msgs/msg/LaserScan param=input_topic
    pub_ = create_publisher<sensor_msgs::msg::LaserScan>(output, 5);  // expect: publisher scan_filtered sensor_msgs/msg/LaserScan param=output_topic
    status_ = create_publisher<std_msgs::msg::String>(status_topic_, 1);  // expect: publisher status std_msgs/msg/String param=status_topic
    diag_ = create_publisher<std_msgs::msg::String>(diagnostics_topic_, 1);  // expect: publisher ~/diagnostics std_msgs/msg/String
    raw_ = create_subscription<LaserScan>(built, 10, cb_);  // expect: subscription ? sensor_msgs/msg/LaserScan unresolved
    other_ = create_subscription<LaserScan>(twice, 10, cb_);  // expect: subscription ? sensor_msgs/msg/LaserScan unresolved
    computed_ = create_subscription<LaserScan>(topic_for("scan"), 10, cb_);  // expect: subscription ? sensor_msgs/msg/LaserScan unresolved
    stop_ = create_service<std_srvs::srv::Trigger>(fixed, stop_cb_);  // expect: service /emergency_stop std_srvs/srv/Trigger
    std::string unknown_default;
    this->get_parameter("extra_topic", unknown_default);
    extra_ = create_publisher<std_msgs::msg::String>(unknown_default, 1);  // expect: publisher ? std_msgs/msg/String param=extra_topic unresolved
  }

private:
  std::string status_topic_ = "status_unused_default";
  std::string diagnostics_topic_;
  rclcpp::Subscription<LaserScan>::SharedPtr sub_, raw_, other_, computed_;
  rclcpp::Publisher<LaserScan>::SharedPtr pub_;
};

}  // namespace demo_cpp

void attach(rclcpp::Node::SharedPtr node, const std::string & name)
{
  auto sub = rclcpp::create_subscription<sensor_msgs::msg::LaserScan>(  // expect: subscription ? sensor_msgs/msg/LaserScan unresolved
    node, name, 10, [](sensor_msgs::msg::LaserScan::ConstSharedPtr) {});
  auto client = node->create_client<std_srvs::srv::Trigger>("reset");  // expect: client reset std_srvs/srv/Trigger
}
