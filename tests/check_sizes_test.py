#!/usr/bin/env python3
"""check_sizes.py on small repositories made for the purpose: a function one
line over its tree's limit, or one uniform too many set by name, must fail
it; the same at the limit must pass."""
import os
import subprocess
import sys
import unittest

from made_repo import repo_with

CHECK = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'check_sizes.py')


def function(name, lines):
    """A C++ function `lines` lines long, first and last line included."""
    body = ''.join(f'  x += {i};\n' for i in range(lines - 4))
    return f'int {name}() {{\n  int x = 0;\n{body}  return x;\n}}\n'


def uniforms(count):
    return 'void draw(Program& program) {\n' + ''.join(
        f'  program.set("u_value{i}", {i});\n' for i in range(count)) + '}\n'


def check(files):
    run = subprocess.run([sys.executable, CHECK, repo_with(files)], capture_output=True, text=True)
    return run.returncode, run.stdout + run.stderr


class Sizes(unittest.TestCase):
    def test_functions_at_the_limits_pass(self):
        status, out = check({'server/a.cpp': function('a', 100), 'common/b.cpp': function('b', 100),
                             'client/cli/c.cpp': function('c', 80),
                             'server/render/d.cpp': uniforms(12)})
        self.assertEqual(status, 0, out)
        self.assertIn('longest function in server/: a (server/a.cpp), 100 lines', out)

    def test_a_long_server_function_fails(self):
        status, out = check({'server/scene/a.cpp': function('too_long', 101)})
        self.assertEqual(status, 1, out)
        self.assertIn('server/scene/a.cpp: too_long is 101 lines, more than 100 in server/', out)

    def test_a_long_shared_function_fails(self):
        status, out = check({'common/text/a.cpp': function('too_long', 101)})
        self.assertEqual(status, 1, out)
        self.assertIn('too_long is 101 lines, more than 100 in common/', out)

    def test_the_client_has_the_lower_limit(self):
        status, out = check({'client/cli/a.cpp': function('too_long', 81)})
        self.assertEqual(status, 1, out)
        self.assertIn('client/cli/a.cpp: too_long is 81 lines, more than 80 in client/', out)

    def test_a_uniform_too_many_set_by_name_fails(self):
        status, out = check({'server/render/passes/d.cpp': uniforms(13)})
        self.assertEqual(status, 1, out)
        self.assertIn('13 uniforms set by name under server/render, more than 12', out)
        self.assertIn('server/render/passes/d.cpp:14: u_value12', out)


if __name__ == '__main__':
    unittest.main()
