// message_filters subscribers synchronised, and tf2 broadcasters and listener.
#include "rclcpp/rclcpp.hpp"
#include "message_filters/subscriber.h"
#include "message_filters/time_synchronizer.h"
#include "sensor_msgs/msg/image.hpp"
#include "sensor_msgs/msg/camera_info.hpp"
#include "tf2_ros/buffer.h"
#include "tf2_ros/transform_broadcaster.h"
#include "tf2_ros/static_transform_broadcaster.h"
#include "tf2_ros/transform_listener.h"

typedef message_filters::Subscriber<sensor_msgs::msg::CameraInfo> InfoSubscriber;

class StereoSync : public rclcpp::Node
{
public:
  StereoSync()
  : Node("stereo_sync"),  // expect-node-name: stereo_sync
    info_sub_(this, "left/camera_info")  // expect: subscription left/camera_info sensor_msgs/msg/CameraInfo via=message_filters
  {
    left_sub_.subscribe(this, "left/image_rect");  // expect: subscription left/image_rect sensor_msgs/msg/Image via=message_filters
    message_filters::Subscriber<sensor_msgs::msg::Image> right(this, "right/image_rect");  // expect: subscription right/image_rect sensor_msgs/msg/Image via=message_filters
    tf_broadcaster_ = std::make_unique<tf2_ros::TransformBroadcaster>(*this);  // expect: publisher /tf tf2_msgs/msg/TFMessage via=tf2_ros
    static_broadcaster_ = std::make_shared<tf2_ros::StaticTransformBroadcaster>(this);  // expect: publisher /tf_static tf2_msgs/msg/TFMessage via=tf2_ros
    tf_buffer_ = std::make_unique<tf2_ros::Buffer>(get_clock());
    tf_listener_ = std::make_shared<tf2_ros::TransformListener>(*tf_buffer_);  // expect: subscription /tf tf2_msgs/msg/TFMessage via=tf2_ros ; subscription /tf_static tf2_msgs/msg/TFMessage via=tf2_ros
    right_info_.reset(new InfoSubscriber(this, "right/camera_info"));  // expect: subscription right/camera_info sensor_msgs/msg/CameraInfo via=message_filters
    raw_ = create_generic_publisher("stereo/raw", "sensor_msgs/msg/Image", rclcpp::QoS(1));  // expect: publisher stereo/raw sensor_msgs/msg/Image
  }

private:
  message_filters::Subscriber<sensor_msgs::msg::Image> left_sub_;
  message_filters::Subscriber<sensor_msgs::msg::CameraInfo> info_sub_;
  std::unique_ptr<tf2_ros::TransformBroadcaster> tf_broadcaster_;
  std::shared_ptr<tf2_ros::StaticTransformBroadcaster> static_broadcaster_;
  std::unique_ptr<tf2_ros::Buffer> tf_buffer_;
  std::shared_ptr<tf2_ros::TransformListener> tf_listener_;
  rclcpp::GenericPublisher::SharedPtr raw_;
  std::unique_ptr<InfoSubscriber> right_info_;
};
