#!/usr/bin/env python3
"""PrairieLearn's own rules for the elements `frustum export prairielearn` writes, written for
Frustum's tests from the elements' code (apps/prairielearn/elements/*/*.py, prepare() and
parse()): what makes a question fail to render, and which submissions an input refuses before
the external grader sees them. For each question directory: server.py's generate() is run for
every variant, question.html's Mustache tags are filled from that variant, and each element is
checked as PrairieLearn would.

Usage: prairielearn_elements.py QUESTION_DIR...   (exit status 1 and the reasons on failure)
"""
import html.parser
import importlib.util
import json
import os
import re
import sys

# check_attribs(): an attribute outside these lists is an error. The lists are those every
# recent PrairieLearn accepts (the intersection of its versions), so a question renders on each.
ALLOWED = {
    "pl-checkbox": {"answers-name", "weight", "number-answers", "min-correct", "max-correct",
                    "fixed-order", "inline", "hide-answer-panel", "hide-help-text",
                    "detailed-help-text", "partial-credit", "partial-credit-method",
                    "hide-letter-keys", "hide-score-badge", "min-select", "max-select",
                    "show-number-correct"},
    "pl-multiple-choice": {"answers-name", "weight", "number-answers", "fixed-order", "inline",
                           "hide-letter-keys", "none-of-the-above", "all-of-the-above",
                           "allow-blank"},
    "pl-string-input": {"answers-name", "weight", "correct-answer", "label", "suffix", "display",
                        "remove-leading-trailing", "remove-spaces", "allow-blank", "ignore-case",
                        "placeholder", "size", "show-help-text"},
    "pl-answer": {"correct", "feedback"},
    "pl-external-grader-results": set(),
    "pl-question-panel": set(), "pl-submission-panel": set(), "pl-answer-panel": set(),
}


class Elements(html.parser.HTMLParser):
    """The pl-* elements of a rendered question.html, each with its attributes and children."""

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.stack, self.found = [], []

    def handle_starttag(self, tag, attrs):
        node = {"tag": tag, "attrs": dict(attrs), "children": [], "text": ""}
        if self.stack:
            self.stack[-1]["children"].append(node)
        if tag.startswith("pl-"):
            self.found.append(node)
        self.stack.append(node)

    def handle_endtag(self, tag):
        while self.stack:
            if self.stack.pop()["tag"] == tag:
                break

    def handle_data(self, data):
        if self.stack:
            self.stack[-1]["text"] += data


def fill(template, data):
    """The Mustache tags question.html uses: {{a.b.c}} and {{{a.b.c}}} by path, and the
    {{#a.b}}…{{/a.b}} sections (shown when the value is truthy)."""
    def value(path):
        v = data
        for part in path.strip().split("."):
            v = v.get(part) if isinstance(v, dict) else None
        return v
    template = re.sub(r"\{\{#([^}]+)\}\}(.*?)\{\{/\1\}\}",
                      lambda m: m.group(2) if value(m.group(1)) else "", template, flags=re.S)
    template = re.sub(r"\{\{\{([^}]+)\}\}\}", lambda m: str(value(m.group(1)) or ""), template)
    return re.sub(r"\{\{([^}]+)\}\}", lambda m: str(value(m.group(1)) or ""), template)


def boolean(text):
    # pl.get_boolean_attrib: true/t/1/True/T/TRUE/yes/y/Yes/Y/YES and the false words.
    return str(text).strip() in ("true", "t", "1", "True", "T", "TRUE", "yes", "y", "Yes", "Y", "YES")


def check_question(directory):
    errors = []
    spec = importlib.util.spec_from_file_location("server", os.path.join(directory, "server.py"))
    server = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(server)
    template = open(os.path.join(directory, "question.html"), encoding="utf-8").read()
    info = json.load(open(os.path.join(directory, "info.json"), encoding="utf-8"))
    image = info.get("externalGradingOptions", {}).get("image", "")
    # PrairieLearn pulls the image by name from a registry: ACCOUNT/NAME[:TAG] on Docker Hub.
    if not re.fullmatch(r"[a-z0-9][a-z0-9._-]*(/[a-z0-9][a-z0-9._-]*)+(:[A-Za-z0-9._-]+)?", image):
        errors.append(f"the grader image {image!r} is not a name a registry serves")
    for variant in server.VARIANTS:
        data = {"params": {}, "correct_answers": {}}
        data["params"].update(variant["params"])
        data["correct_answers"].update(variant["correct_answers"])
        parser = Elements()
        parser.feed(fill(template, data))
        for e in parser.found:
            tag, attrs = e["tag"], e["attrs"]
            if tag in ("pl-number-input", "pl-matrix-input"):
                # Their parse() refuses sqrt(14)/14 and `none`, which Frustum accepts.
                errors.append(f"{tag} {attrs.get('answers-name')}: refuses exact forms and none")
                continue
            if tag not in ALLOWED:
                errors.append(f"unknown element {tag}")
                continue
            bad = set(attrs) - ALLOWED[tag]
            if bad:
                errors.append(f"{tag}: attributes {sorted(bad)} are refused (check_attribs)")
            name = attrs.get("answers-name")
            options = [c for c in e["children"] if c["tag"] == "pl-answer"]
            right = [c for c in options if boolean(c["attrs"].get("correct", "false"))]
            if tag == "pl-checkbox":
                if not right:
                    errors.append(f"pl-checkbox {name}: At least one option must be true.")
                if "min-correct" in attrs and int(attrs["min-correct"]) < 1:
                    errors.append(f"pl-checkbox {name}: min-correct must be at least 1")
                if name in data["correct_answers"]:
                    errors.append(f"pl-checkbox {name}: Duplicate correct_answers variable name")
            if tag == "pl-multiple-choice":
                if len(right) < 1:
                    errors.append(f"pl-multiple-choice {name}: no correct answer")
                if name in data["correct_answers"]:
                    errors.append(f"pl-multiple-choice {name}: Duplicate correct_answers variable name")
            if tag == "pl-string-input":
                # parse(): a blank submission is a format error unless allow-blank; the key
                # the answer panel shows must itself be a submission this input takes.
                key = data["correct_answers"].get(name)
                if not isinstance(key, str) or not key.strip():
                    errors.append(f"pl-string-input {name}: no key for the answer panel")
                if "placeholder" in attrs and "[1-3, 2-7]" in attrs["placeholder"] and \
                        re.match(r"\s*\[\s*\[", str(key)):
                    errors.append(f"pl-string-input {name}: an edge-list placeholder for rows {key}")
        if "{{{feedback.results.frustum_html}}}" not in template:
            errors.append("the submission panel does not show Frustum's feedback")
    return errors


def main():
    failed = 0
    for directory in sys.argv[1:]:
        for error in sorted(set(check_question(directory))):
            print(f"{directory}: {error}")
            failed += 1
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
