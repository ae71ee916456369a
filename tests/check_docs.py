#!/usr/bin/env python3
"""The documentation holds together: README.md is a short front door and
docs/ holds the rest, so a moved or renamed file must not leave a link
pointing nowhere, and a page nobody links to is a page nobody finds.

    tests/check_docs.py [REPO_ROOT]     (default: the folder above this one)

Fails (exit status 1, every problem printed) when
  - a relative link or image in README.md or docs/**/*.md names a file or
    folder that does not exist (the #anchor and ?query are not checked);
  - a page docs/**/*.md cannot be reached from README.md by following
    relative links from Markdown file to Markdown file (a link to a folder
    reaches the folder's README.md, as the repository's web view shows it);
  - README.md is longer than 300 lines;
  - a path in backticks names no file or folder of the repository (see
    `code_paths`): a doc that names a file is a doc a reader follows.
Standard library only, so it runs wherever CMake found a Python 3.
"""
import glob
import os
import re
import sys
from urllib.parse import unquote

README_MAX_LINES = 300

# [text](target "title"), ![alt](target): the text may hold one level of
# brackets; the target may be wrapped in <...>.
INLINE_LINK = re.compile(r'!?\[(?:[^\[\]]|\[[^\[\]]*\])*\]\(\s*(<[^>]*>|[^\s)]+)(?:\s+"[^"]*"|\s+\'[^\']*\')?\s*\)')
# [label]: target, a reference definition on a line of its own.
REFERENCE_DEFINITION = re.compile(r'^ {0,3}\[[^\]]+\]:\s*(<[^>]*>|\S+)', re.MULTILINE)
# <img src="..."> and <a href="...">, as the README writes its pictures.
HTML_LINK = re.compile(r'<(?:img|a|source)\b[^>]*?\b(?:src|href)\s*=\s*(?:"([^"]*)"|\'([^\']*)\')', re.IGNORECASE)
SCHEME = re.compile(r'^[A-Za-z][A-Za-z0-9+.-]*:')
FENCE = re.compile(r'^ {0,3}(```+|~~~+)')
INLINE_CODE = re.compile(r'(`+)(?:(?!\1).)+?\1')


def prose(text):
    """The text without code: fenced blocks, indented blocks and code spans
    hold examples, not links. Lines keep their places (code becomes blank)."""
    out = []
    fence = None
    in_indented = False
    previous_blank = True
    for line in text.split('\n'):
        stripped = line.strip()
        if fence:
            if stripped.startswith(fence):
                fence = None
            out.append('')
            previous_blank = False
            continue
        opening = FENCE.match(line)
        if opening:
            fence = opening.group(1)[0] * 3
            out.append('')
            continue
        indented = line.startswith('    ') or line.startswith('\t')
        if indented and (previous_blank or in_indented) and stripped:
            in_indented = True
            out.append('')
            continue
        if stripped:
            in_indented = False
        previous_blank = not stripped
        # A code span inside a link's text still leaves the link visible.
        out.append(INLINE_CODE.sub('code', line))
    return '\n'.join(out)


def link_targets(text):
    """(line number, target) of every link and image in the Markdown text."""
    text = prose(text)
    found = []
    for pattern in (INLINE_LINK, REFERENCE_DEFINITION):
        for match in pattern.finditer(text):
            found.append((text.count('\n', 0, match.start()) + 1, match.group(1).strip('<>')))
    for match in HTML_LINK.finditer(text):
        found.append((text.count('\n', 0, match.start()) + 1, match.group(1) or match.group(2) or ''))
    return sorted(found)


# A code span that reads as a path: words joined by slashes, or one file
# name with an extension the repository's own sources have. `<name>`,
# `{id}` and `*` stand for any part of a name.
SLASHED = re.compile(r'^[\w.-]+(/[\w.{}*<>+-]+)+/?$')
SOURCE_FILE = re.compile(r'^[\w.-]+\.(cpp|h|py|sh|mjs|glsl|cmake)$')
# Media types read as paths of the image folder; they are not.
MEDIA_TYPE = re.compile(r'^(image|application|text|multipart)/(png|webp|jpeg|svg\+xml|json|plain|html|form-data)$')
# Names the docs give to files that exist only once built or run, and the
# shared folder beside the checkout.
NOT_IN_TREE = ('build', 'build-asan', '..')
# A path may leave out the folders every reader knows: `render/frame_plan`
# is server/render/plan/frame_plan.{h,cpp} read from server/.
EXTENSIONS = ('', '.*')


def tree_folders(root):
    folders = []
    for folder, names, _ in os.walk(root):
        names[:] = [n for n in names if not n.startswith('.') and n not in ('node_modules',) + NOT_IN_TREE]
        folders.append(folder)
    return folders


def as_glob(path):
    return re.sub(r'<[^>]*>|\{[^}]*\}', '*', path)


def names_something(root, folders, path):
    """Whether `path` names a file or folder from the root or from any
    folder of the tree, with or without its extension."""
    pattern = as_glob(path.rstrip('/'))
    for folder in [root] + folders:
        for ext in EXTENSIONS:
            if glob.glob(os.path.join(folder, pattern + ext)):
                return True
    return False


def code_paths(text):
    """(line number, path) of every code span that reads as a path of the
    repository: slashed paths whose first folder the repository has (an
    HTTP route, a MIME type or a URL is not one), and source file names."""
    found = []
    for match in re.finditer(r'(`+)((?:(?!\1).)+?)\1', text, re.DOTALL):
        span = match.group(2).strip()
        if ' ' in span or span.split('/')[0] in NOT_IN_TREE or MEDIA_TYPE.match(span):
            continue
        if SLASHED.match(span) or SOURCE_FILE.match(span):
            found.append((text.count('\n', 0, match.start()) + 1, span))
    return found


def dead_code_paths(root, page, folders):
    problems = []
    top_names = {os.path.basename(f) for f in folders}
    for line, path in code_paths(read(page)):
        if '/' in path and as_glob(path.split('/')[0]) not in top_names and '*' not in as_glob(path.split('/')[0]):
            continue
        if not names_something(root, folders, path):
            problems.append(f'{os.path.relpath(page, root)}:{line}: `{path}` names no file of the repository')
    return problems


def is_relative(target):
    return bool(target) and not target.startswith('#') and not target.startswith('//') \
        and not SCHEME.match(target)


def resolve(root, linking_file, target):
    """The path a relative target names: from the linking file's folder, or
    from the repository's root for a target starting with /."""
    path = unquote(re.split(r'[#?]', target, maxsplit=1)[0])
    if not path:
        return linking_file  # "?query" or "#anchor" alone: the file itself
    base = root if path.startswith('/') else os.path.dirname(linking_file)
    return os.path.normpath(os.path.join(base, path.lstrip('/')))


def markdown_behind(path):
    """The Markdown file a link to `path` shows, or None."""
    if os.path.isdir(path):
        readme = os.path.join(path, 'README.md')
        return readme if os.path.isfile(readme) else None
    return path if path.endswith('.md') and os.path.isfile(path) else None


def read(path):
    with open(path, encoding='utf-8') as f:
        return f.read()


def docs_pages(root):
    pages = []
    for folder, _, files in os.walk(os.path.join(root, 'docs')):
        pages.extend(os.path.join(folder, f) for f in files if f.endswith('.md'))
    return sorted(os.path.normpath(p) for p in pages)


def main():
    root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), '..'))
    readme = os.path.join(root, 'README.md')
    problems = []
    if not os.path.isfile(readme):
        print(f'{readme}: missing')
        return 1

    checked = [readme] + docs_pages(root)
    for page in checked:
        for line, target in link_targets(read(page)):
            if is_relative(target) and not os.path.exists(resolve(root, page, target)):
                problems.append(f'{os.path.relpath(page, root)}:{line}: dead link "{target}"')

    folders = tree_folders(root)
    for page in checked:
        problems.extend(dead_code_paths(root, page, folders))

    # Every page reached by following links from the README, through any
    # Markdown file of the repository on the way.
    reached = {readme}
    waiting = [readme]
    while waiting:
        page = waiting.pop()
        for _, target in link_targets(read(page)):
            if not is_relative(target):
                continue
            behind = markdown_behind(resolve(root, page, target))
            if behind and behind not in reached:
                reached.add(behind)
                waiting.append(behind)
    for page in checked[1:]:
        if page not in reached:
            problems.append(f'{os.path.relpath(page, root)}: not reachable from README.md by relative links')

    lines = len(read(readme).splitlines())
    if lines > README_MAX_LINES:
        problems.append(f'README.md: {lines} lines, more than {README_MAX_LINES}: move a section into docs/')

    for problem in problems:
        print(problem)
    if problems:
        print(f'check_docs: {len(problems)} problem(s)')
        return 1
    print(f'check_docs: README.md ({lines} lines) and {len(checked) - 1} docs pages: '
          f'every relative link resolves, every page is reached')
    return 0


if __name__ == '__main__':
    sys.exit(main())
