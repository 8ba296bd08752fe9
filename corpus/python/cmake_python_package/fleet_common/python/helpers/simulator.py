"""Finds the simulator the way vendors' helpers do: its folder, its version file, a prompt."""
import os
import re

import vendor_errors  # not installed here: its names are unknown


class Version:
    def __init__(self, text):
        parts = re.findall(r'R(\d+)([a-d])', text)
        self.year = int(parts[0][0])
        self.release = ord(parts[0][1]) - ord('a')


def simulator_version(home='/opt/simulator'):
    if not os.path.isdir(home):
        return None
    with open(os.path.join(home, 'version.txt')) as file:
        return Version(file.read().strip())


def ask_to_install():
    try:
        answer = input('Install the simulator? [y/N] ')
    except vendor_errors.PromptError:
        return False
    if answer.lower() == 'y':
        raise vendor_errors.InstallError('installing is not supported here')
    return False
