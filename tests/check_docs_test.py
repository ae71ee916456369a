#!/usr/bin/env python3
"""check_docs.py on small repositories made for the purpose: it must fail
on what it is there to catch, or a green run of it says nothing."""
import os
import subprocess
import sys
import unittest

from made_repo import repo_with

CHECK = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'check_docs.py')


def check(root):
    run = subprocess.run([sys.executable, CHECK, root], capture_output=True, text=True)
    return run.returncode, run.stdout


class CodePaths(unittest.TestCase):
    SOURCES = {'server/render/plan/frame_plan.cpp': '', 'server/render/plan/frame_plan.h': '',
               'docs/page.md': 'Back to the [front door](../README.md).\n'}

    def readme(self, text):
        return repo_with(dict(self.SOURCES, **{'README.md': text + '\n[page](docs/page.md)\n'}))

    def test_paths_that_exist_pass(self):
        status, out = check(self.readme('See `server/render/plan/frame_plan.cpp`, `render/plan/frame_plan` '
                                        'and `frame_plan.h`; it answers `image/png`.'))
        self.assertEqual(status, 0, out)

    def test_a_path_from_before_a_move_fails(self):
        status, out = check(self.readme('The plan is made in `render/frame_plan`.'))
        self.assertEqual(status, 1, out)
        self.assertIn('`render/frame_plan` names no file', out)

    def test_a_file_name_that_is_nowhere_fails(self):
        status, out = check(self.readme('See `pass_plan.cpp`.'))
        self.assertEqual(status, 1, out)
        self.assertIn('`pass_plan.cpp` names no file', out)

    def test_a_placeholder_matches_any_name(self):
        status, out = check(self.readme('Each pass in `server/render/plan/<name>.cpp`.'))
        self.assertEqual(status, 0, out)


if __name__ == '__main__':
    unittest.main()
