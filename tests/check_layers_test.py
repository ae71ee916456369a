#!/usr/bin/env python3
"""check_layers.py on small repositories made for the purpose: each holds
one include the table forbids, a chain of includes to a room the table
says may not be reached, or a folder no room holds, and must fail."""
import os
import subprocess
import sys
import unittest

from made_repo import repo_with

CHECK = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'check_layers.py')


def check(files):
    run = subprocess.run([sys.executable, CHECK, repo_with(files)], capture_output=True, text=True)
    return run.returncode, run.stdout


HEADERS = {'server/render/passes/passes.h': '', 'server/pipeline/pipeline.h': '',
           'server/scene/mesh/model.h': '', 'common/image/image.h': '', 'client/cli/cli_args.h': ''}


class Fences(unittest.TestCase):
    def test_includes_the_table_allows_pass(self):
        status, out = check(dict(HEADERS, **{'server/http/routes.cpp': '#include "pipeline/pipeline.h"\n',
                                             'client/cli/main.cpp': '#include "cli_args.h"\n'
                                                                    '#include "image/image.h"\n'}))
        self.assertEqual(status, 0, out)

    def test_http_reaching_a_pass_fails(self):
        status, out = check(dict(HEADERS, **{'server/http/routes.cpp': '#include "render/passes/passes.h"\n'}))
        self.assertEqual(status, 1, out)
        self.assertIn('server/http/routes.cpp:1: includes render/passes/passes.h, of server/render/passes', out)

    def test_http_reaching_the_gpu_through_a_header_it_may_include_fails(self):
        status, out = check(dict(HEADERS, **{'server/gpu/egl_context.h': '',
                                             'server/pipeline/pipeline.h': '#include "gpu/egl_context.h"\n',
                                             'server/http/routes.cpp': '#include "pipeline/pipeline.h"\n'}))
        self.assertEqual(status, 1, out)
        self.assertIn('server/http/routes.cpp: reaches server/gpu/egl_context.h, of server/gpu, which server/http may '
                      'not reach: server/http/routes.cpp -> server/pipeline/pipeline.h -> server/gpu/egl_context.h',
                      out)
        self.assertIn('; 1 problems', out)

    def test_the_cli_including_a_daemon_header_fails(self):
        status, out = check(dict(HEADERS, **{'client/cli/main.cpp': '#include "scene/mesh/model.h"\n'}))
        self.assertEqual(status, 1, out)
        self.assertIn('which client/cli may not include', out)

    def test_a_shared_library_including_the_daemon_fails(self):
        status, out = check(dict(HEADERS, **{'common/image/png.cpp': '#include "scene/mesh/model.h"\n'}))
        self.assertEqual(status, 1, out)

    def test_a_benchmark_reaching_the_http_layer_fails(self):
        status, out = check(dict(HEADERS, **{'server/http/routes.h': '',
                                             'bench/b.cpp': '#include "http/routes.h"\n'}))
        self.assertEqual(status, 1, out)

    def test_a_folder_in_no_room_fails(self):
        status, out = check(dict(HEADERS, **{'server/newroom/x.cpp': ''}))
        self.assertEqual(status, 1, out)
        self.assertIn('server/newroom/x.cpp: in no room', out)


class Drawing(unittest.TestCase):
    def drawing(self):
        return subprocess.run([sys.executable, CHECK, '--diagram'], capture_output=True, text=True).stdout.strip()

    def page(self, drawn):
        return ('# Architecture\n<!-- rooms: drawn by tests/check_layers.py --diagram -->\n' + drawn +
                '\n<!-- rooms: end -->\n')

    def test_the_tables_own_drawing_passes(self):
        status, out = check(dict(HEADERS, **{'docs/architecture.md': self.page(self.drawing())}))
        self.assertEqual(status, 0, out)

    def test_a_drawing_that_is_not_the_tables_fails(self):
        moved = self.drawing().replace('server/app', 'server/apps')
        status, out = check(dict(HEADERS, **{'docs/architecture.md': self.page(moved)}))
        self.assertEqual(status, 1, out)
        self.assertIn('its drawing of the rooms is not the table', out)

    def test_a_page_without_the_drawing_fails(self):
        status, out = check(dict(HEADERS, **{'docs/architecture.md': '# Architecture\n'}))
        self.assertEqual(status, 1, out)
        self.assertIn('no drawing of the rooms', out)


if __name__ == '__main__':
    unittest.main()
