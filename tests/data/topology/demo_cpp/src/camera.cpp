// image_transport publishers and subscribers, camera pairs included.
#include "rclcpp/rclcpp.hpp"
#include "image_transport/image_transport.hpp"

class Camera : public rclcpp::Node
{
public:
  Camera()
  : Node("camera")  // expect-node-name: camera
  {
    raw_ = image_transport::create_publisher(this, "image_raw");  // expect: publisher image_raw sensor_msgs/msg/Image via=image_transport
    rect_ = image_transport::create_camera_publisher(this, "rect/image");  // expect: publisher rect/image sensor_msgs/msg/Image via=image_transport ; publisher rect/camera_info sensor_msgs/msg/CameraInfo via=image_transport
  }

  void start_transport()
  {
    it_ = std::make_shared<image_transport::ImageTransport>(shared_from_this());
    mono_ = it_->advertise("mono", 1);  // expect: publisher mono sensor_msgs/msg/Image via=image_transport
    input_ = it_->subscribe("input", 1, &Camera::on_image, this);  // expect: subscription input sensor_msgs/msg/Image via=image_transport
    stereo_ = it_->subscribeCamera("/stereo/left/image", 1, &Camera::on_camera, this);  // expect: subscription /stereo/left/image sensor_msgs/msg/Image via=image_transport ; subscription /stereo/left/camera_info sensor_msgs/msg/CameraInfo via=image_transport
    depth_ = image_transport::create_subscription(  // expect: subscription depth sensor_msgs/msg/Image via=image_transport
      this, "depth", [](const sensor_msgs::msg::Image::ConstSharedPtr &) {}, "raw");
  }

private:
  std::shared_ptr<image_transport::ImageTransport> it_;
  image_transport::Publisher raw_, mono_;
  image_transport::CameraPublisher rect_;
  image_transport::Subscriber input_, depth_;
  image_transport::CameraSubscriber stereo_;
};
