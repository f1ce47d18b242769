"""The README's Python section runs as written: its code block, and the
command whose output it shows prints that output."""
import re
import subprocess
import sys

from conftest import REPO, child_env


def python_section():
    text = (REPO / "README.md").read_text()
    return text[text.index("## From Python"):text.index("## Layout")]


def test_the_readme_python_block_runs():
    block = re.search(r"```python\n(.*?)```", python_section(), re.S).group(1)
    r = subprocess.run([sys.executable, "-W", "ignore", "-c", block], capture_output=True, text=True, cwd=REPO,
                       env=child_env(), timeout=600)
    assert r.returncode == 0, r.stderr


def test_the_readme_command_prints_what_it_shows():
    shown = re.search(r"```\n\$ v/bin/python -c \"(.*?)\"\n(.*?)\n```", python_section(), re.S)
    code, output = shown.group(1), shown.group(2)
    r = subprocess.run([sys.executable, "-W", "ignore", "-c", code], capture_output=True, text=True, cwd=REPO,
                       env=child_env(), timeout=600)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == output.strip()
