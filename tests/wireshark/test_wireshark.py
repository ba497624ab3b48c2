#!/usr/bin/env python3
"""The generated Wireshark dissectors, run by tshark on captures written from
robowire's encoders, must show for every packet exactly what robowire's own
decoders make of the same bytes (NAME.json, written next to each capture).

usage: test_wireshark.py CAPTURE_WRITER DISSECTOR_GENERATOR [ROBOWIRE_CLI]
(with the CLI: `robowire dissector all --output DIR` must write the same plugins)
"""
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile

failures = []


def fail(msg):
    failures.append(msg)
    print("FAIL:", msg)


def run_all(commands, env):
    procs = [subprocess.Popen(c, stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env, text=True)
             for c in commands]
    return [p.communicate() + (p.returncode,) for p in procs]


def check_stderr(what, err):
    for line in err.splitlines():
        if "Running as user" in line or "This could be dangerous" in line:
            continue
        if line.strip():
            fail(f"{what}: stderr: {line}")


def walk(node, out, experts, bad):
    """Collects every key's values (repeated keys: in order) below node."""
    if isinstance(node, list):
        for n in node:
            walk(n, out, experts, bad)
        return
    if not isinstance(node, dict):
        return
    for key, value in node.items():
        if key.startswith("_ws.lua.error") or key.startswith("_ws.malformed"):
            bad.append(key)
        if key == "_ws.expert.message":
            experts.extend(value if isinstance(value, list) else [value])
        if isinstance(value, (dict, list)) and (key.endswith("_tree") or key.startswith("_ws.") or
                                                 isinstance(value, dict) or
                                                 any(isinstance(v, dict) for v in value)):
            walk(value, out, experts, bad)
        else:
            out.setdefault(key, []).extend(value if isinstance(value, list) else [value])


def find_trees(node, proto):
    """Every tree of the protocol, wherever it is nested (BLE: inside btatt)."""
    found = []
    if isinstance(node, list):
        for n in node:
            found += find_trees(n, proto)
    elif isinstance(node, dict):
        for key, value in node.items():
            if key == proto:
                found += value if isinstance(value, list) else [value]
            else:
                found += find_trees(value, proto)
    return found


def same(expected, shown):
    if isinstance(expected, str):
        return expected == shown
    try:
        v = float(shown)
    except (TypeError, ValueError):
        return False
    if expected == 0:
        return abs(v) < 1e-9
    return math.isclose(v, expected, rel_tol=2e-6)


def check_capture(name, expected, packets):
    proto = expected["protocol"]
    by_number = {int(p["_source"]["layers"]["frame"]["frame.number"]): p["_source"]["layers"] for p in packets}
    if len(by_number) != len(expected["packets"]):
        fail(f"{name}: tshark shows {len(by_number)} packets, {len(expected['packets'])} written")
    noise = 0
    messages_seen = 0
    for number_text, messages in expected["packets"].items():
        number = int(number_text)
        layers = by_number.get(number)
        if layers is None:
            fail(f"{name} #{number}: missing")
            continue
        out, experts, bad = {}, [], []
        walk(layers, out, experts, bad)
        if bad:
            fail(f"{name} #{number}: {bad}")
        noise += sum(int(v) for v in out.get(f"{proto}.noise", []))
        trees = find_trees(layers, proto)
        if len(trees) != len(messages):
            fail(f"{name} #{number}: {len(trees)} {proto} messages shown, robowire decodes {len(messages)}")
            continue
        for tree, exp in zip(trees, messages):
            messages_seen += 1
            fields, tree_experts, _ = {}, [], []
            walk(tree, fields, tree_experts, [])
            shown_name = (fields.get(f"{proto}.message") or [None])[0]
            if shown_name != exp["message"]:
                fail(f"{name} #{number}: message {shown_name!r}, robowire decodes {exp['message']!r}")
                continue
            if "expert" in exp:
                want = exp["expert"]
                if not any(want in e for e in tree_experts):
                    fail(f"{name} #{number}: no warning naming {want!r} (warnings: {tree_experts})")
                continue
            if tree_experts:
                fail(f"{name} #{number}: unexpected warnings {tree_experts}")
            prefix = f"{proto}.{exp['message']}."
            for key, values in exp["fields"].items():
                shown = fields.get(key, [])
                if len(shown) != len(values) or not all(same(e, s) for e, s in zip(values, shown)):
                    fail(f"{name} #{number} {key}: tshark {shown}, robowire {values}")
            for key, values in fields.items():
                if key.startswith(prefix) and key not in exp["fields"] and not all(v == "" for v in values):
                    fail(f"{name} #{number}: {key} shown, robowire has no such value")
            if "json" in exp:
                shown = fields.get(f"{proto}.json", [])
                if shown != [exp["json"]]:
                    fail(f"{name} #{number}: reassembled text {shown}, robowire {exp['json']!r}")
    if noise != expected["noise"]:
        fail(f"{name}: {noise} noise bytes shown, robowire's scanner skipped {expected['noise']}")
    return messages_seen


def main():
    writer, generator = sys.argv[1], sys.argv[2]
    if shutil.which("tshark") is None:
        print("tshark is not installed (apt-get install tshark)")
        return 1
    with tempfile.TemporaryDirectory() as tmp:
        home = os.path.join(tmp, "home")
        plugins = os.path.join(home, ".local", "lib", "wireshark", "plugins")
        os.makedirs(plugins)
        subprocess.run([generator, "all", plugins], check=True)
        if len(sys.argv) > 3:
            from_cli = os.path.join(tmp, "cli")
            os.makedirs(from_cli)
            subprocess.run([sys.argv[3], "dissector", "all", "--output", from_cli], check=True)
            for p in ("buwizz3", "navbot", "osp"):
                a = open(os.path.join(plugins, f"robowire_{p}.lua")).read()
                b = open(os.path.join(from_cli, f"robowire_{p}.lua")).read()
                if a != b or len(a) < 1000:
                    fail(f"robowire dissector {p}: not the generator's plugin")
        caps = os.path.join(tmp, "captures")
        os.makedirs(caps)
        subprocess.run([writer, caps], check=True)
        env = {"HOME": home, "PATH": os.environ.get("PATH", "/usr/bin:/bin"), "LANG": "C.UTF-8"}

        captures = ["buwizz3.pcap", "buwizz3.btsnoop", "navbot.pcap", "navbot.btsnoop", "osp.pcapng"]
        commands = [["tshark", "-G", "fields"]]
        commands += [["tshark", "-r", os.path.join(caps, c), "-T", "json", "--no-duplicate-keys"] for c in captures]
        results = run_all(commands, env)

        out, err, rc = results[0]
        check_stderr("tshark -G fields", err)
        registered = {line.split("\t")[2] for line in out.splitlines() if line.startswith("F\t")}
        for c in captures:
            exp = json.load(open(os.path.join(caps, c.split(".")[0] + ".json")))
            for msgs in exp["packets"].values():
                for m in msgs:
                    for key in m.get("fields", {}):
                        if key not in registered:
                            fail(f"field {key} is not registered")

        total = 0
        for c, (out, err, rc) in zip(captures, results[1:]):
            check_stderr(c, err)
            if rc != 0:
                fail(f"{c}: tshark exit {rc}")
                continue
            exp = json.load(open(os.path.join(caps, c.split(".")[0] + ".json")))
            n = check_capture(c, exp, json.loads(out))
            total += n
        print(f"{total} messages in {len(captures)} captures compared")
    if failures:
        print(f"{len(failures)} failures")
        return 1
    print("ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
