from setuptools import setup

package_name = "demo_py"

setup(
    name=package_name,
    version="0.0.1",
    packages=[package_name],
    data_files=[
        ("share/ament_index/resource_index/packages", ["resource/" + package_name]),
        ("share/" + package_name, ["package.xml"]),
    ],
    install_requires=["setuptools"],
    entry_points={
        "console_scripts": [
            "listener = demo_py.listener:main",
            "turtle_follower = demo_py.follower:main",
            "countdown = demo_py.countdown:main",
            "missing = demo_py.not_there:main",
        ],
    },
)
