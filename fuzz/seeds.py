#!/usr/bin/env python3
"""Writes the seed corpora: the golden vectors of the unit tests (worked out by
hand from the protocol documents) plus edge cases. Run from the repository
root; files are named by content, so re-running adds nothing twice."""
import hashlib, os, sys

if sys.argv[1:2] in (["-h"], ["--help"]):  # usage: the docstring
    print(__doc__)
    sys.exit(0)
def h(s): return bytes.fromhex(s.replace(' ', ''))

buwizz3_commands = [
    "20 4D 79 42 72 69 63 6B 00 00 00 00 00", "21 01 2C 01 00 00 10 0E 00 00",
    "22 00 00 80 3F 00 00 80 BF 00 00 00 3F 9A 99 19 3F 00 00 20 C0 00 00 00 00", "23",
    "30 7F 81 00 40 C0 01 21 3F", "31 E8 03 00 00 18 FC FF FF 00 00 00 00 78 56 34 12 81 64 03 00",
    "32 32", "33 01 02 03 04 05 06 00 0D 64 FF 07 08", "34 0B", "35 05", "36",
    "36 FF 00 00 00 FF 00 00 00 FF 10 20 30", "36 FF 00 00 00 FF 00 00 00 FF 10 20 30 1F F0 08 55",
    "37 0B", "38 32 32 32 32 64 64", "40 10 02 00 C2 01 00", "50 10 14 15 00", "51 03",
    "52 FF FF FF FF 00 00 00 00 5A 00 00 00 FF FF FF 7F",
    "53 00 00 00 00 00 66 66 66 3F 00 00 00 00 CD CC CC 3E 0A D7 23 3C CD CC 4C BF 00 00 A0 41 00 00 00 00 64 02 02 15",
    "A1", "AC", "30 80 00 00 00 00 00 00 00", "37 04", "",
]
status68 = ("01 73 50 0A 14 1E 28 32 C8 23 F0 FF F0 7F 00 08 0B 0C 0D 0E 0F 7D 30 EC 4C FF 60 79 FE FF "
            "31 64 B3 00 40 E2 01 00 4B FF 01 00 01 00 00 00 4C 7F FF FF FF FF FF 7F "
            "9A 99 19 3F 00 00 20 C0 00 00 4C 41 F9 2A")
buwizz3_notifications = [status68, status68[:54 * 3 - 1], status68 + " EE EE",
                         "23 00 00 80 3F 00 00 80 BF 00 00 00 3F 9A 99 19 3F 00 00 20 C0 00 00 00 00",
                         "AC 01 02 03", "AC", status68[:60 * 3 - 1]]
buwizz3_adv = ["0B 02 01 06 08 09 42 75 57 69 7A 7A 33 09 FF 4E 05 42 57 03 22 34 12"
               " 11 06 93 6E 67 B1 19 99 B3 88 81 44 FB 74 D1 92 05 50",
               "03 02 01 06 09 FF 4E 05 42 57 42 4C 00 00", "04 02 01 06 09 FF 4E"]
navbot_frames = [
    "55 AA 10 00 00 9C 64 37 FF 02 01 01 02 FB 05 00 00 00 00 00",
    "55 AA 10 00 00 00 00 F6 00 01 00 00 00 00 00 00 00 00 00 00",
    "55 AA 10 00 00 00 00 8A 00 01 00 00 00 00 00 00 00 00 00 00",
    "55 AA 10 00 00 00 00 00 8A 00 01 00 00 00 00 00 00 00 00 00 00 00",
    "55 AA 02 01 00 7B 22 74 79 70 65 22 3A 22 67 65 74 5F 64 65",
    "55 AA 02 00 00 76 69 63 65 5F 69 6E 66 6F 22 7D 00 00 00 00",
]
navbot_reassembly = [
    "14" + "55 AA 02 01 00 7B 22 74 79 70 65 22 3A 22 67 65 74 5F 64 65" + "14" +
    "55 AA 02 00 00 76 69 63 65 5F 69 6E 66 6F 22 7D 00 00 00 00",
    "14 55 AA 02 02 00 61 61 61 61 61 61 61 61 61 61 61 61 61 61 61 14 55 AA 01 01 00 62 62 62 62 62 62 62 62 62 62 62 62 62 62 62",
]
osp_frames = ["FF AA 00 01 00 00 00 00 55 77", "FF AA 00 11 02 00 00 00 55 77", "FF AA 01 02 03 34 12 00 55 77",
              "FF AA 02 01 00 00 00 00 55 77", "FF AA 02 04 00 00 00 00 55 77", "FF AA 02 11 FF FF 00 00 55 77",
              "FF AA 02 12 D2 04 00 00 55 77", "FF AA 02 13 24 FA 00 00 55 77", "FF AA 02 14 03 05 00 00 55 77",
              "FF AA 03 01 0A 0B 0C 0D 55 77", "FF AA 02 14 05 00 00 00 55 77"]
osp_streams = ["01 00 55 77 FF FF AA 01 02 03 04 05 06 07 08 FF AA 02 11 FF AA 00 00 55 77 FF AA 02 12 D2 04 00 00 55 77",
               "07 FF AA 02 11 12 FF AA 02 12 D2 04 00 00 55 77", "03 " + " ".join(osp_frames)]
# core_types: an operation byte (modulo 12) and its operands
core_types = ["00 01 00 02 00 03 00 04 00 05 00 06 00 07 00 08 00 09 00 0A 00 0B 00 0C 00 0D",  # push_back past capacity
              "01 0F " + "AA " * 15 + "02 04 00 02 0F 00 03 05 03 0F 02 00 01",  # append too much, resize, clear, zeros
              "04 0E " + "11 " * 14 + "04 03 01 02 03 05 03 01 02 03 05 02 01 02",  # from, comparisons
              "06 0B 62 75 77 69 7A 7A 33 2D 72 65 64 06 04 6C 6F 77 21",  # text of 11 and of 4 characters
              "08 80 FF 08 8A 8A 08 7F 00 09 FF 00 FF FF FF FF 00 09 10 11 FF FF FF FF 10 0A 02 0A 04 0A 06",
              "0B FF FF FF FF FF FF FF FF 00 00 00 00 00 00 00 00 00 00 08 01 02 03 04 05 06 07 08",  # empty range
              "0B 00 00 00 00 00 00 00 00 00 FF FF FF FF FF FF FF FF 00 08 01 02 03 04 05 06 07 08",  # 0..2^64-1
              "07 02 01 06 08 09 42 75 57 69 7A 7A 33 00 00",  # AD structures, then padding
              "07 02 01 06 09 FF 4E 05"]  # a length past the end
roundtrip = ["00", "05 01 2C 01 00 00", "0A 01 FF 00 00 00 FF 00 00 00 FF 10 20 30 01 1F F0 08 55",
             "80 73 50 0A 14 1E 28 32 C8", "82 05 01 02 03 04 05", "11 7F C0 00 01"]

sets = {
    "buwizz3_command": buwizz3_commands, "buwizz3_notification": buwizz3_notifications,
    "buwizz3_advertisement": buwizz3_adv, "navbot_frame": navbot_frames,
    "navbot_reassembler": navbot_reassembly, "osp_decode": osp_frames, "osp_scanner": osp_streams,
    "core_types": core_types, "roundtrip_buwizz3": roundtrip, "roundtrip_navbot": roundtrip, "roundtrip_osp": roundtrip,
}
# The differential harnesses: the same vectors behind their mode byte.
sets["diff_buwizz3"] = ["00 " + v for v in buwizz3_commands] + ["01 " + v for v in buwizz3_notifications] + \
    ["02 " + v for v in roundtrip] + ["03 " + v for v in roundtrip]
sets["diff_navbot"] = ["00 " + v for v in navbot_frames] + ["01 " + v for v in roundtrip]
sets["diff_osp"] = ["00 " + v for v in osp_frames] + ["01 " + v for v in roundtrip]
for name, vectors in sets.items():
    d = os.path.join("fuzz", "corpus", name)
    os.makedirs(d, exist_ok=True)
    for v in vectors:
        b = h(v)
        with open(os.path.join(d, "seed-" + hashlib.sha1(b).hexdigest()[:16]), "wb") as f:
            f.write(b)
