from setuptools import setup

package_name = 'py_pkg'

setup(
    name=package_name,
    packages=[package_name],
    data_files=[
        ('share/' + package_name, ['package.xml']),
        ('lib/' + package_name, ['scripts/helper.sh']),
    ],
    entry_points={
        'console_scripts': [
            'planner = py_pkg.planner:main',
            'executor = py_pkg.executor:main',
        ],
    },
)
