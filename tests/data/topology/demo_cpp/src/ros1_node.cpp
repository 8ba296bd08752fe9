// ROS 1 code left in a ROS 2 workspace: NodeHandle::advertise<T> is not image_transport,
// and nothing here creates a ROS 2 endpoint. No expectation: nothing may be found.
#include <ros/ros.h>
#include <sensor_msgs/Imu.h>

class Ros1Filter
{
public:
  explicit Ros1Filter(ros::NodeHandle nh)
  : nh_(nh)
  {
    pub_ = nh_.advertise<sensor_msgs::Imu>("imu/data", 5);
    sub_ = nh_.subscribe("imu/data_raw", 5, &Ros1Filter::on_imu, this);
  }

private:
  void on_imu(const sensor_msgs::Imu::ConstPtr &) {}

  ros::NodeHandle nh_;
  ros::Publisher pub_;
  ros::Subscriber sub_;
};
