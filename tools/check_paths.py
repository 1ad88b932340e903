#!/usr/bin/env python3
"""Fails when a Markdown file or a comment names a repository path that does not exist.

Checked (ctest Source.Paths; docs: CONTRIBUTING.md, "Checks before a commit"):
- every *.md of the repository (not build trees): each repository path it names (a word that
  starts with one of the repository's top-level directories, such as `solver/raster/fill.hpp`,
  `tools/setup.sh`, `docs/grading.md`, or a top-level file such as CONTRIBUTING.md) exists, and
  each link to another file resolves (relative to the page), with its #anchor when it names a
  heading of a Markdown page;
- every comment (`//`, `/* */` and `#` comments) of the sources under SOURCE_DIRS: each
  repository path it names exists.
A path with a placeholder (`<name>`, `{a,b}`, `...`, `…`, `$VAR`) names no one file and is
skipped; a `*` is a glob that must match something. Paths under build trees are not checked.

Each run first plants a bad path, a bad link and a bad anchor in a temporary tree and fails
unless each is reported (`--self-test` runs only that).
"""
import os
import pathlib
import re
import subprocess
import sys
import tempfile

SOURCE_DIRS = ["solver", "grader", "report", "batch", "export", "app", "server", "tests",
               "bench", "tools", "fuzz"]
SOURCE_EXTS = {".cpp", ".hpp", ".h", ".cc", ".py", ".sh", ".cmake", ".txt", ".in"}
HASH_COMMENTS = {".py", ".sh", ".cmake", ".txt", ".in"}
# Top-level files, and the style guide's file name, which a comment once named though the
# repository does not hold it (the layers and checks are in CONTRIBUTING.md).
TOP_FILES = ["README.md", "CONTRIBUTING.md", "CMakeLists.txt", ".clang-format", "STYLE.md"]
SKIP_PARTS = {"build", ".git"}

LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")
FENCE = re.compile(r"^\s*(```|~~~)")


def top_dirs(root):
    return sorted(p.name for p in root.iterdir()
                  if p.is_dir() and not p.name.startswith(".") and p.name not in SKIP_PARTS
                  and not p.name.startswith("build")) + [".ci"]


def path_pattern(root):
    dirs = "|".join(re.escape(d) for d in top_dirs(root))
    files = "|".join(re.escape(f) for f in TOP_FILES)
    # A repository path: a top-level directory followed by a path, or a top-level file; not
    # preceded by a character that would make it part of a longer path or a word.
    return re.compile(r"(?<![\w./\-~$@])((?:%s)/[\w.\-/*<>{},…]*|(?:%s)(?![\w.]))" % (dirs, files))


def is_placeholder(path):
    return any(s in path for s in ("<", ">", "{", "}", "...", "…", ",")) or path.endswith(".")


def is_prose(path):
    # "report/grade", "batch/export": two words with a slash, no file name, no trailing slash.
    return path.count("/") == 1 and "." not in path.split("/")[-1] and not path.endswith("/")


def clean(path):
    path = path.rstrip(".,;:)")
    return path


def exists(root, path):
    if "*" in path:
        return any(root.glob(path))
    return (root / path).exists()


def slug(heading):
    # GitHub's anchors: lower case, punctuation dropped (but - and _), spaces to -.
    text = re.sub(r"`", "", heading.strip().lower())
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def anchors(md_path):
    out, seen, fenced = set(), {}, False
    for line in md_path.read_text(encoding="utf-8").splitlines():
        if FENCE.match(line):
            fenced = not fenced
        if fenced:
            continue
        m = re.match(r"^#{1,6}\s+(.*?)\s*#*\s*$", line)
        if m:
            s = slug(m.group(1))
            n = seen.get(s, 0)
            seen[s] = n + 1
            out.add(s if n == 0 else "%s-%d" % (s, n))
    return out


def listed_files(root):
    try:
        out = subprocess.run(["git", "-C", str(root), "ls-files", "--cached", "--others",
                              "--exclude-standard"], capture_output=True, text=True, check=True)
        names = out.stdout.splitlines()
    except (OSError, subprocess.CalledProcessError):
        names = [str(p.relative_to(root)) for p in root.rglob("*") if p.is_file()]
    return [n for n in names
            if not any(part in SKIP_PARTS or part.startswith("build") for part in
                       pathlib.PurePath(n).parts[:-1]) and (root / n).is_file()]


def comments(text, ext):
    """(line number, comment text) of every comment in a source file."""
    out = []
    if ext in HASH_COMMENTS:
        for n, line in enumerate(text.splitlines(), 1):
            m = re.search(r"(?:^|\s)#(?![!{(])(.*)$", line)
            if m:
                out.append((n, m.group(1)))
        return out
    # C++: drop string and character literals (keeping line breaks), then find comments.
    i, n, line = 0, len(text), 1
    while i < n:
        c = text[i]
        if c == "\n":
            line += 1
            i += 1
        elif text.startswith("//", i):
            end = text.find("\n", i)
            end = n if end < 0 else end
            out.append((line, text[i + 2:end]))
            i = end
        elif text.startswith("/*", i):
            end = text.find("*/", i + 2)
            end = n if end < 0 else end
            body = text[i + 2:end]
            for k, part in enumerate(body.split("\n")):
                out.append((line + k, part))
            line += body.count("\n")
            i = end + 2
        elif text.startswith('R"', i) and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            open_paren = text.find("(", i)
            delim = text[i + 2:open_paren]
            end = text.find(")" + delim + '"', open_paren)
            end = n if end < 0 else end + len(delim) + 2
            line += text.count("\n", i, end)
            i = end
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            i = j + 1
        else:
            i += 1
    return out


def check(root):
    pattern = path_pattern(root)
    errors = []
    md_anchor_cache = {}

    def named_paths(rel, n, text):
        for m in pattern.finditer(text):
            path = clean(m.group(1))
            if not path or is_placeholder(path) or is_prose(path):
                continue
            if not exists(root, path):
                errors.append("%s:%d: names %s, which does not exist" % (rel, n, path))

    for rel in listed_files(root):
        p = root / rel
        ext = p.suffix
        if ext == ".md":
            text = p.read_text(encoding="utf-8")
            for n, line in enumerate(text.splitlines(), 1):
                named_paths(rel, n, line)
                for m in LINK.finditer(line):
                    target = m.group(1)
                    if re.match(r"^[a-z][a-z0-9+.\-]*:", target):
                        continue  # a URL
                    file_part, _, anchor = target.partition("#")
                    dest = p if not file_part else (p.parent / file_part)
                    if not dest.exists():
                        errors.append("%s:%d: links to %s, which does not exist" % (rel, n, target))
                        continue
                    if anchor and dest.suffix == ".md":
                        key = dest.resolve()
                        if key not in md_anchor_cache:
                            md_anchor_cache[key] = anchors(dest)
                        if anchor not in md_anchor_cache[key]:
                            errors.append("%s:%d: links to %s, whose page has no heading #%s"
                                          % (rel, n, target, anchor))
        elif (ext in SOURCE_EXTS or p.name == "CMakeLists.txt") and \
                pathlib.PurePath(rel).parts[0] in SOURCE_DIRS:
            try:
                text = p.read_text(encoding="utf-8")
            except UnicodeDecodeError:
                continue
            for n, comment in comments(text, ".txt" if p.name == "CMakeLists.txt" else ext):
                named_paths(rel, n, comment)
    return errors


def self_test():
    with tempfile.TemporaryDirectory() as tmp:
        root = pathlib.Path(tmp)
        (root / "docs").mkdir()
        (root / "tools").mkdir()
        (root / "report").mkdir()
        (root / "docs" / "a.md").write_text("# Title\n\n## A section\n")
        (root / "README.md").write_text(
            "See `tools/real.sh`, `tools/planted_missing.sh` and [a](docs/a.md#a-section),\n"
            "[b](docs/missing.md), [c](docs/a.md#no-such-heading), `docs/<name>.md`.\n"
            "The style is in STYLE.md; what to report/grade.\n")
        (root / "tools" / "real.sh").write_text(
            "# uses tools/real.sh and tools/gone.py\necho 'tools/in_a_string.sh'\n")
        (root / "tools" / "x.cpp").write_text(
            '// see solver/none.hpp\nconst char* s = "tools/not_a_comment.hpp";\n')
        got = "\n".join(check(root))
        want = ["README.md:1: names tools/planted_missing.sh", "README.md:2: links to docs/missing.md",
                "README.md:2: links to docs/a.md#no-such-heading", "tools/real.sh:1: names tools/gone.py",
                "README.md:3: names STYLE.md"]
        missing = [w for w in want if w not in got]
        wrong = [w for w in ("tools/real.sh,", "a-section", "in_a_string", "not_a_comment", "<name>",
                                  "report/grade")
                 if w in got]
        # The planted tree has no solver directory, so x.cpp's comment names no repository path.
        if missing or wrong:
            print("check_paths.py self-test failed:\n  not reported: %s\n  reported wrongly: %s\n%s"
                  % (missing, wrong, got))
            return 1
    print("check_paths.py self-test: a planted bad path, link and anchor are reported")
    return 0


def main():
    # The check first shows it can fail (ctest Source.Paths runs both).
    failed = self_test()
    if failed or "--self-test" in sys.argv[1:]:
        return failed
    root = pathlib.Path(__file__).resolve().parent.parent
    errors = check(root)
    for e in errors:
        print(e)
    if errors:
        print("%d path(s) named but missing" % len(errors))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
