"""The small repositories the checkers' self-tests make: each file written
under a fresh temporary folder, its folders made on the way."""
import os
import tempfile


def repo_with(files):
    """The folder holding `files` (repository path → text)."""
    root = tempfile.mkdtemp(prefix='made_repo_')
    for path, text in files.items():
        os.makedirs(os.path.dirname(os.path.join(root, path)), exist_ok=True)
        with open(os.path.join(root, path), 'w', encoding='utf-8') as f:
            f.write(text)
    return root
