#!/usr/bin/env python3
"""The docs-cli-flags test: docs/cli.md's flag table, the option table and --help agree.

    check-cli-page.py MEDIAL_AXIS PAGE [--write]

MEDIAL_AXIS is the built command-line program; its hidden --help-table prints the option
table of Examples/Cxx/MedialAxisOptions.cxx (Flags()): long name, short name, kind (switch,
text, count, number), range and default. PAGE (docs/cli.md) holds one row per flag between
<!-- cli-flags:begin --> and <!-- cli-flags:end -->:

    | `--samples N`, `-n N` | 1 to 1e15 (10000) | what it does |

Checked, flag by flag:
  - the rows name the table's flags in the table's order, each with its short name when it
    has one, and no other flag;
  - a switch's row says `switch` and names no value; any other flag names its value
    (`--samples N`);
  - a count or number flag's row starts with its range, `LO to HI` as the table has it
    (`above LO` when the table has no upper bound);
  - the default: `(D...)` after the range or `` `D` (default) `` in a list of values,
    exactly as the table spells it; a row shows no default the table does not have;
  - the meaning is written (not empty, not TODO);
  - --help has a paragraph for every flag of the table (and for no other flag), naming its
    short name, and says `default D` or `D (default` in it when the table has a default.

--write rewrites PAGE's rows in the table's order: rows of flags no longer in the table
go, new flags get a row with their range and default and a TODO meaning (which the check
then refuses until it is written).
"""
import re
import subprocess
import sys

BEGIN, END = "<!-- cli-flags:begin -->", "<!-- cli-flags:end -->"
VALUE_NAMES = {"text": "VALUE", "count": "N", "number": "X"}


def flag_table(cli):
    out = subprocess.run([cli, "--help-table"], check=True, stdout=subprocess.PIPE, text=True).stdout
    flags = []
    for line in out.splitlines():
        long_name, short, kind, lo, hi, default = line.split("\t")
        flags.append({"long": long_name, "short": short, "kind": kind, "lo": float(lo), "hi": float(hi),
                      "default": default})
    if not flags:
        sys.exit("FAIL %s --help-table printed no flags" % cli)
    return flags


def help_paragraphs(cli):
    """{flag spelling: paragraph text} for the paragraphs of --help that start with flags."""
    out = subprocess.run([cli, "--help"], check=True, stdout=subprocess.PIPE, text=True).stdout
    paragraphs, current = [], None
    for line in out.splitlines():
        if re.match(r"^  -", line):
            current = [line]
            paragraphs.append(current)
        elif current is not None and re.match(r"^ {4,}", line):
            current.append(line)
        else:
            current = None
    named = {}
    for lines in paragraphs:
        text = " ".join(l.strip() for l in lines)
        head = re.split(r"\s{2,}", lines[0].strip())[0]  # the flags, then the text
        for token in head.split():
            token = token.rstrip(",")
            if re.match(r"^--?[A-Za-z][\w-]*$", token):
                named.setdefault(token, text)
            elif not re.match(r"^[A-Z][A-Za-z.]*$", token):
                break  # the flags and their value names come first
    return named


def page_rows(page):
    text = open(page, encoding="utf-8").read()
    if BEGIN not in text or END not in text:
        sys.exit("FAIL %s: no %s ... %s block" % (page, BEGIN, END))
    head, rest = text.split(BEGIN, 1)
    block, tail = rest.split(END, 1)
    first_line = head.count("\n") + 2
    rows = []
    for offset, line in enumerate(block.strip("\n").split("\n")):
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) < 3 or cells[0] == "flag" or set(cells[0]) <= set("-: "):
            continue
        spelled = re.findall(r"`([^`]+)`", cells[0])
        rows.append({"line": first_line + offset, "spelled": spelled, "values": cells[1],
                     "meaning": " | ".join(cells[2:]), "text": line})
    return text, head, block, tail, rows


def row_default(values):
    match = re.search(r"`([^`]+)` \(default\)", values)
    if match:
        return match.group(1)
    match = re.search(r"\(([^;:),]+)", values)
    return match.group(1).strip() if match else ""


def same_number(text, value):
    try:
        return float(text) == value
    except ValueError:
        return False


def check_row(flag, row):
    problems = []
    where = "line %d, %s" % (row["line"], "--" + flag["long"])
    names = [s.split()[0] for s in row["spelled"]]
    expected = ["--" + flag["long"]] + (["-" + flag["short"]] if flag["short"] else [])
    if names != expected:
        problems.append("%s: the row names %s, the table %s" % (where, " ".join(names), " ".join(expected)))
    takes_value = flag["kind"] != "switch"
    for spelled in row["spelled"]:
        if takes_value and len(spelled.split()) < 2:
            problems.append("%s: `%s` takes a value; name it (`%s VALUE`)" % (where, spelled, spelled))
        if not takes_value and len(spelled.split()) > 1:
            problems.append("%s: `%s` is a switch and takes no value" % (where, spelled))
    values = row["values"]
    if not takes_value and values != "switch":
        problems.append("%s: a switch: its values cell says `switch`, not '%s'" % (where, values))
    if flag["kind"] in ("count", "number"):
        if flag["hi"] >= 1e300:
            match = re.match(r"^above (\S+?),?(\s|$)", values)
            if not match or not same_number(match.group(1), flag["lo"]):
                problems.append("%s: the table's range has no upper bound: the cell starts 'above %g', not '%s'"
                                % (where, flag["lo"], values))
        else:
            match = re.match(r"^(\S+) to (\S+?)(\s|$)", values)
            if not match or not same_number(match.group(1), flag["lo"]) or not same_number(match.group(2), flag["hi"]):
                problems.append("%s: the table's range is %.17g to %.17g; the cell says '%s'"
                                % (where, flag["lo"], flag["hi"], values))
    shown = row_default(values) if takes_value else ""
    if shown != flag["default"]:
        if flag["default"]:
            problems.append("%s: the table's default is '%s'; the cell shows '%s' (write '(%s)' after the range, "
                            "or '`%s` (default)')" % (where, flag["default"], shown, flag["default"], flag["default"]))
        else:
            problems.append("%s: the cell shows a default, '%s', that the table does not have" % (where, shown))
    if not row["meaning"] or row["meaning"].upper().startswith("TODO"):
        problems.append("%s: say what the flag does" % where)
    return problems


def check_help(flags, named):
    problems = []
    known = set()
    for flag in flags:
        long_name = "--" + flag["long"]
        known.add(long_name)
        paragraph = named.get(long_name)
        if paragraph is None:
            problems.append("--help: no paragraph for %s" % long_name)
            continue
        if flag["short"]:
            known.add("-" + flag["short"])
            if named.get("-" + flag["short"]) != paragraph:
                problems.append("--help: %s's paragraph does not name -%s" % (long_name, flag["short"]))
        default = flag["default"]
        if default and not re.search(r"(default %s(?![\w.])|(?<![\w.])%s \(default)"
                                     % (re.escape(default), re.escape(default)), paragraph):
            problems.append("--help: %s's paragraph does not say 'default %s'" % (long_name, default))
    for spelled in sorted(set(named) - known):
        problems.append("--help: a paragraph for %s, which is not in the flag table" % spelled)
    return problems


def skeleton(flag):
    value = VALUE_NAMES.get(flag["kind"], "")
    spelled = ["`--%s%s`" % (flag["long"], " " + value if value else "")]
    if flag["short"]:
        spelled.append("`-%s%s`" % (flag["short"], " " + value if value else ""))
    if flag["kind"] == "switch":
        values = "switch"
    elif flag["kind"] in ("count", "number"):
        values = ("above %g" % flag["lo"]) if flag["hi"] >= 1e300 else "%g to %g" % (flag["lo"], flag["hi"])
        if flag["default"]:
            values += " (%s)" % flag["default"]
    else:
        values = "`%s` (default)" % flag["default"] if flag["default"] else "VALUE"
    return "| %s | %s | TODO: what it does |" % (", ".join(spelled), values)


def main(argv):
    if len(argv) < 3:
        sys.exit(__doc__)
    cli, page = argv[1], argv[2]
    flags = flag_table(cli)
    text, head, block, tail, rows = page_rows(page)

    if "--write" in argv[3:]:
        by_flag = {}
        for row in rows:
            if row["spelled"]:
                by_flag[row["spelled"][0].split()[0]] = row["text"]
        lines = [l for l in block.strip("\n").split("\n")[:2]]  # the header and its rule
        lines += [by_flag.get("--" + f["long"], skeleton(f)) for f in flags]
        with open(page, "w", encoding="utf-8") as f:
            f.write(head + BEGIN + "\n" + "\n".join(lines) + "\n" + END + tail)
        print("wrote %d rows to %s" % (len(flags), page))
        return 0

    problems = []
    table_names = ["--" + f["long"] for f in flags]
    row_names = [row["spelled"][0].split()[0] if row["spelled"] else "" for row in rows]
    for index, name in enumerate(table_names):
        if name not in row_names:
            after = "after the row of %s" % table_names[index - 1] if index else "first"
            problems.append("no row for %s, flag %d of the table: add it %s" % (name, index + 1, after))
    for row, name in zip(rows, row_names):
        if name not in table_names:
            problems.append("line %d: a row for '%s', which is not in the flag table" % (row["line"], name))
    common_rows = [n for n in row_names if n in table_names]
    common_table = [n for n in table_names if n in row_names]
    if common_rows != common_table:
        first = next(i for i, (a, b) in enumerate(zip(common_rows, common_table)) if a != b)
        problems.append("the rows are not in the table's order: %s comes where the table has %s "
                        "('--write' puts them in order)" % (common_rows[first], common_table[first]))
    by_name = dict(zip(row_names, rows))
    for flag in flags:
        if "--" + flag["long"] in by_name:
            problems += check_row(flag, by_name["--" + flag["long"]])
    problems += check_help(flags, help_paragraphs(cli))

    for problem in problems:
        print("FAIL " + problem)
    print("docs-cli-flags: %d flags in the table, %d rows in %s, %d problem(s)" % (len(flags), len(rows), page, len(problems)))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
