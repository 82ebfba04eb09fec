#!/usr/bin/env python3
"""Writes a manual page (roff, man(7)) from a program's own --help, so that the page never
says anything the program does not. For a program with commands (pkm), each command's
`PROGRAM COMMAND --help` becomes a subsection of COMMANDS.

  manpage.py --program PATH --name NAME --summary TEXT --version TEXT
             [--commands] [--sections FILE] -o OUT.1

The help is read as the programs print it for an 80-column terminal: "Usage: …" is the
synopsis; a block of lines that start with "  -" is a list of options (an option, then its
description, continued on more deeply indented lines); a heading ending in ':' starts a
subsection; a block of aligned columns is kept as it is; other blocks are paragraphs.
--sections adds hand-written sections (EXAMPLES, FILES, SEE ALSO): "[TITLE]" lines followed
by roff.
"""

import argparse
import datetime
import os
import re
import subprocess
import sys

OPTION = re.compile(r"^  (-\S.*?)(?:\s{2,}(\S.*))?$")


def escape(text):
    """Text as roff reads it literally: backslashes, hyphens, and a leading '.' or "'"."""
    text = text.replace("\\", "\\e").replace("-", "\\-")
    return "\\&" + text if text[:1] in (".", "'") else text


def run_help(program, *arguments):
    environment = {**os.environ, "QT_QPA_PLATFORM": "offscreen", "LC_ALL": "C.UTF-8", "COLUMNS": "80"}
    done = subprocess.run([program, *arguments, "--help"], capture_output=True, text=True, env=environment)
    if done.returncode != 0 or not done.stdout.strip():
        sys.exit(f"manpage.py: '{program} {' '.join(arguments)} --help' failed: {done.stderr.strip()}")
    # Qt prints the program as it was started: name it as a user types it
    return done.stdout.replace(program, os.path.basename(program))


def blocks(text):
    block = []
    for line in text.rstrip().splitlines():
        if line.strip():
            block.append(line.rstrip())
        elif block:
            yield block
            block = []
    if block:
        yield block


def options(lines):
    """'  --opt ARG   description' entries, continued on indented lines, as .TP items."""
    out = []
    for line in lines:
        match = OPTION.match(line)
        if match:
            out += [".TP", "\\fB" + escape(match.group(1)) + "\\fR"]
            if match.group(2):
                out.append(escape(match.group(2)))
        else:
            out.append(escape(line.strip()))
    return out


def body(text, skip_usage=True):
    """The roff of a help text after its "Usage:" line."""
    out = []
    for block in blocks(text):
        if skip_usage and block[0].startswith("Usage:"):
            rest = block[1:]
            if not rest:
                continue
            block = rest
        heading = None
        if block[0].endswith(":") and not block[0].startswith(" ") and len(block) > 1:
            heading, block = block[0][:-1], block[1:]
        if heading:
            out += [".SS " + escape(heading)]
        # runs of indented lines (options, aligned columns) and of plain ones (a paragraph)
        runs = []
        for line in block:
            indented = line.startswith(" ")
            if runs and runs[-1][0] == indented:
                runs[-1][1].append(line)
            else:
                runs.append((indented, [line]))
        for indented, lines in runs:
            if indented and OPTION.match(lines[0]):
                out += options(lines)
            elif indented or re.search(r"\S {3,}\S", "\n".join(lines)):
                # aligned columns (a list of commands, exit statuses): kept as printed
                out += [".PP", ".nf"] + [escape(line) for line in lines] + [".fi"]
            else:
                out += [".PP", escape(" ".join(line.strip() for line in lines))]
    return out


def usage(text):
    for line in text.splitlines():
        if line.startswith("Usage:"):
            return line[len("Usage:"):].strip()
    return ""


def sections(path):
    """{TITLE: roff lines} of a file of [TITLE] sections of hand-written roff."""
    found, title = {}, None
    if path:
        with open(path, encoding="utf-8") as file:
            for line in file.read().splitlines():
                match = re.fullmatch(r"\[(.+)\]", line.strip())
                if match:
                    title = match.group(1)
                    found[title] = []
                elif title:
                    found[title].append(line)
    return found


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--program", required=True)
    parser.add_argument("--name", required=True)
    parser.add_argument("--summary", required=True)
    parser.add_argument("--version", required=True)
    parser.add_argument("--commands", action="store_true", help="document each COMMAND --help too")
    parser.add_argument("--sections")
    parser.add_argument("-o", "--output", required=True)
    options_ = parser.parse_args()

    text = run_help(options_.program)
    date = datetime.datetime.fromtimestamp(
        int(os.environ.get("SOURCE_DATE_EPOCH", datetime.datetime.now().timestamp())), datetime.timezone.utc)
    page = [
        '.\\" -*- coding: UTF-8 -*-',
        f'.\\" Made by cmake/manpage.py from {options_.name} --help; edit the program\'s help, not this file.',
        f'.TH {options_.name.upper()} 1 "{date:%Y-%m-%d}" "PKM Studio {options_.version}" "User Commands"',
        ".SH NAME",
        f"{escape(options_.name)} \\- {escape(options_.summary)}",
        ".SH SYNOPSIS",
        ".B " + escape(usage(text)),
        ".SH DESCRIPTION",
    ]
    extra = sections(options_.sections)
    page += extra.pop("DESCRIPTION", [])  # before the help's own words, which are brief in a GUI's
    page += body(text)
    if options_.commands:
        names = []
        in_commands = False
        for line in text.splitlines():
            if line.strip() == "Commands:":
                in_commands = True
            elif in_commands and not line.strip():
                break
            elif in_commands and re.match(r"^  [a-z]", line):
                name = line.split()[0]
                if name not in names:
                    names.append(name)
        page.append(".SH COMMANDS")
        for name in names:
            command = run_help(options_.program, name)
            page += [".SS " + escape(f"{options_.name} {name}"), ".B " + escape(usage(command))]
            page += body(command)
    for title, lines in extra.items():
        page += [".SH " + title] + lines
    with open(options_.output + ".part", "w", encoding="utf-8") as file:
        file.write("\n".join(page) + "\n")
    os.replace(options_.output + ".part", options_.output)


if __name__ == "__main__":
    main()
