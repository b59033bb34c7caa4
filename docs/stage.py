#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Stages the documentation site's source for `mkdocs build` (./build.sh docs runs it).

    docs/stage.py REPO OUT [--cli-reference FILE]

Writes OUT, the site's docs_dir: every page of REPO/docs/, the pages that live elsewhere in the
tree (plugin_api/ABI.md as sdk/abi.md, CHANGES.md as changes.md, SECURITY.md as security.md), the CLI reference the program
generates (FILE, as reference/cli.md), and every other file of the tree a page links to (pictures
in bench/results/, the JSON Schemas, a script), copied under _repo/ with its path in the tree.

Pages are written with links relative to themselves in the source tree, so that they work when
the tree is browsed (and in the installed SDK guide); the copies here get their links rewritten
to where the targets land in OUT. A link to a file that does not exist, to a folder (a site
cannot show one) or to a heading a page does not have is an error: the script prints each one and
exits 1. mkdocs then checks the links again in strict mode.
"""

import argparse
import os
import re
import shutil
import sys
import unicodedata

# Pages kept outside docs/, and where they go in the site.
PAGES_ELSEWHERE = {
    "plugin_api/ABI.md": "sdk/abi.md",
    "CHANGES.md": "changes.md",
    "SECURITY.md": "security.md",
}
# Pages the build generates: (the page's path as if it were in the tree, its place in the site).
GENERATED_CLI_REFERENCE = ("docs/reference/cli.md", "reference/cli.md")
# Files in docs/ that are not part of the site.
NOT_SITE = {"docs/stage.py"}
# Where files outside docs/ that pages link to are copied.
COPIES = "_repo"

LINK = re.compile(r"(!?\[[^\]]*\]\()([^)\s]+)(\))")
FENCE = re.compile(r"^\s*(```|~~~)")
HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*#*\s*$")


def slugify(text):
    """A heading's anchor as Python-Markdown's toc extension (mkdocs' default) makes it."""
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", text)  # a link's text
    text = text.replace("`", "").replace("*", "")
    text = unicodedata.normalize("NFKD", text).encode("ascii", "ignore").decode("ascii")
    text = re.sub(r"[^\w\s-]", "", text).strip().lower()
    return re.sub(r"[-\s]+", "-", text)


def prose_lines(text):
    """(index, line) of the lines outside fenced code blocks."""
    fenced = False
    for index, line in enumerate(text.split("\n")):
        if FENCE.match(line):
            fenced = not fenced
            continue
        if not fenced:
            yield index, line


def anchors(text):
    found = set()
    for _, line in prose_lines(text):
        match = HEADING.match(line)
        if match:
            slug = slugify(match.group(2))
            unique, n = slug, 0
            while unique in found:  # toc numbers repeated headings
                n += 1
                unique = f"{slug}_{n}"
            found.add(unique)
    return found


def code_spans(line):
    """The (start, end) of each inline code span of a line."""
    return [m.span() for m in re.finditer(r"(`+)[^`]*?\1", line)]


class Stager:
    def __init__(self, repo, out, generated):
        self.repo = repo
        self.out = out
        self.generated = generated  # tree path -> (source file, site path)
        self.errors = []
        self.pages = {}  # tree path -> site path, of the pages to write
        self.queue = []
        self.texts = {}

    def site_path(self, tree_path):
        """Where a file of the tree lands in the site, queueing pages and copying other files."""
        if tree_path in self.generated:
            site = self.generated[tree_path][1]
        elif tree_path in PAGES_ELSEWHERE:
            site = PAGES_ELSEWHERE[tree_path]
        elif tree_path.startswith("docs/"):
            site = tree_path[len("docs/"):]
        else:
            site = f"{COPIES}/{tree_path}"
        if tree_path.endswith(".md"):
            if tree_path not in self.pages:
                self.pages[tree_path] = site
                self.queue.append(tree_path)
        elif not os.path.exists(os.path.join(self.out, site)):
            os.makedirs(os.path.dirname(os.path.join(self.out, site)), exist_ok=True)
            shutil.copyfile(os.path.join(self.repo, tree_path), os.path.join(self.out, site))
        return site

    def text(self, tree_path):
        if tree_path not in self.texts:
            source = self.generated.get(tree_path, (os.path.join(self.repo, tree_path),))[0]
            with open(source, encoding="utf-8") as f:
                self.texts[tree_path] = f.read()
        return self.texts[tree_path]

    def exists(self, tree_path):
        return tree_path in self.generated or os.path.exists(os.path.join(self.repo, tree_path))

    def rewrite_link(self, page, target):
        if re.match(r"^[a-z][a-z0-9+.-]*:", target) or target.startswith("/"):
            return target  # a URL, mailto:, or an absolute path mkdocs checks itself
        path, _, anchor = target.partition("#")
        tree_target = (os.path.normpath(os.path.join(os.path.dirname(page), path))
                       if path else page)
        if tree_target.startswith(".."):
            self.errors.append(f"{page}: link to {target} leaves the source tree")
            return target
        if not self.exists(tree_target):
            self.errors.append(f"{page}: link to {target}: {tree_target} does not exist")
            return target
        if os.path.isdir(os.path.join(self.repo, tree_target)):
            self.errors.append(f"{page}: link to {target} is a folder, which a site cannot show:"
                               " link a file in it, or name the folder as code")
            return target
        if anchor and tree_target.endswith(".md") and anchor not in anchors(self.text(tree_target)):
            self.errors.append(f"{page}: link to {target}: {tree_target} has no heading #{anchor}")
        site = self.site_path(tree_target)
        if not path:
            return target
        relative = os.path.relpath(site, os.path.dirname(self.pages[page]) or ".")
        return relative + (f"#{anchor}" if anchor else "")

    def stage_page(self, page):
        lines = self.text(page).split("\n")

        for index, line in prose_lines(self.text(page)):
            spans = code_spans(line)

            def rewrite(m):
                if any(start <= m.start() < end for start, end in spans):
                    return m.group(0)  # code that looks like a link
                return m.group(1) + self.rewrite_link(page, m.group(2)) + m.group(3)

            lines[index] = LINK.sub(rewrite, line)
        destination = os.path.join(self.out, self.pages[page])
        os.makedirs(os.path.dirname(destination), exist_ok=True)
        with open(destination, "w", encoding="utf-8") as f:
            f.write("\n".join(lines))

    def run(self):
        for directory, _, files in os.walk(os.path.join(self.repo, "docs")):
            for name in sorted(files):
                tree_path = os.path.relpath(os.path.join(directory, name), self.repo)
                if tree_path not in NOT_SITE:
                    self.site_path(tree_path)
        for tree_path in list(self.generated) + list(PAGES_ELSEWHERE):
            if self.exists(tree_path):
                self.site_path(tree_path)
            else:
                self.errors.append(f"{tree_path}, a page of the site, does not exist")
        while self.queue:
            self.stage_page(self.queue.pop(0))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("repo")
    parser.add_argument("out")
    parser.add_argument("--cli-reference", required=True,
                        help="the CLI reference the build generated (build/docs/cli-reference.md)")
    args = parser.parse_args()
    repo = os.path.realpath(args.repo)
    out = os.path.realpath(args.out)
    if not os.path.isfile(args.cli_reference):
        sys.exit(f"stage.py: no CLI reference at {args.cli_reference}: build the target "
                 "fgr_generated_docs first")
    generated = {GENERATED_CLI_REFERENCE[0]: (os.path.realpath(args.cli_reference),
                                              GENERATED_CLI_REFERENCE[1])}
    if os.path.exists(out):
        shutil.rmtree(out)
    os.makedirs(out)
    stager = Stager(repo, out, generated)
    stager.run()
    for error in stager.errors:
        print(f"stage.py: {error}", file=sys.stderr)
    if stager.errors:
        sys.exit(f"stage.py: {len(stager.errors)} broken links")
    print(f"stage.py: {len(stager.pages)} pages staged in {out}")


if __name__ == "__main__":
    main()
