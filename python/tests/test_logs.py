"""read_log, to_csv and plot against the command-line tool: the same records as
`robowire decode --file LOG --json`, the same table as `--format csv --message M`."""
import io
import json
import subprocess
import sys
from pathlib import Path

import pytest

import robowire
from robowire.logs import _shortest

ROOT = Path(__file__).resolve().parents[2]
SESSION = ROOT / "examples" / "logs" / "session.py"
APP = "50052901-74fb-4481-88b3-9919b1676e93"

# nRF Connect for Android: a status, a command, a bad frame (line 6), another characteristic, a descriptor
ANDROID = "\n".join([
    "nRF Connect, 2026-03-14",
    "I 23:59:59.900 Connected to D4:37:A1:0C:55:2E",
    "I 23:59:59.950 Read Response received from 00002a00-0000-1000-8000-00805f9b34fb, value: (0x) 42-75, \"Bu\"",
    "I 23:59:59.990 Data written to descr. 00002902-0000-1000-8000-00805f9b34fb, value: (0x) 01-00",
    "I 00:00:00.100 Notification received from " + APP + ", value: (0x) 01-6D-50-0A-14-1E-28-32-C8-23-F0-FF-F0-7F-00-08"
    "-0B-0C-0D-0E-0F-7D-30-EC-4C-FF-60-79-FE-FF-31-64-B3-00-40-E2-01-00-4B-FF-01-00-01-00-00-00-4C-7F-FF-FF-FF-FF"
    "-FF-7F-00-00-00-3F-00-00-20-C0-00-00-4C-41-F9-2A",
    "I 00:00:00.200 Data written to " + APP + ", value: (0x) 30-80-00-00-00-00-00-00-00",
    "I 00:00:00.300 Data written to " + APP + ", value: (0x) 30-7F-81-00-40-C0-01-21-3F",
    "I 00:00:00.400 Data written to " + APP + ", value: (0x) 20-4D-79-2C-22-42-22-00-00-00-00-00-00",
]) + "\n"
# nRF Connect for Desktop's log file (handles, not UUIDs: the protocol is given)
DESKTOP = "\n".join([
    "2026-03-14T10:15:01.000Z INFO Connected to device D4:37:A1:0C:55:2E",
    "2026-03-14T10:15:02.331Z INFO Attribute value changed, handle: 0x10, value (0x): 32-32",
    "2026-03-14T10:15:02.332Z INFO Attribute value written, handle: 0x10, value (0x): 32-32",
    "2026-03-14T10:15:03.127Z INFO Attribute value changed, handle: 0x10, value (0x): AC",
]) + "\n"
HEX = "# OSP frames\nFF AA 02 12 D2 04 00 00 55 77\nFF AA 02 12\n"


def cli_json(cli, path, *args):
    p = subprocess.run([cli, "decode", *args, "--file", str(path), "--json"], capture_output=True, text=True, timeout=120)
    return [json.loads(line) for line in p.stdout.splitlines()], p.returncode, p.stderr


def cli_csv(cli, path, message, *args):
    p = subprocess.run([cli, "decode", *args, "--file", str(path), "--format", "csv", "--message", message],
                       capture_output=True, text=True, timeout=120)
    return p.stdout


@pytest.fixture(scope="module")
def logs(tmp_path_factory):
    d = tmp_path_factory.mktemp("logs")
    files = {}
    for name, text in (("android.txt", ANDROID), ("desktop.txt", DESKTOP), ("hex.txt", HEX)):
        files[name] = d / name
        files[name].write_text(text)
    files["session.txt"] = d / "session.txt"  # 5 minutes at 20 Hz
    subprocess.run([sys.executable, str(SESSION), "-o", str(files["session.txt"])], check=True)
    files["10k.txt"] = d / "10k.txt"
    subprocess.run([sys.executable, str(SESSION), "--lines", "10000", "-o", str(files["10k.txt"])], check=True)
    return files


CASES = [("android.txt", None), ("android.txt", "buwizz3"), ("desktop.txt", "buwizz3"), ("desktop.txt", None),
         ("hex.txt", "osp"), ("session.txt", None), ("10k.txt", "buwizz3")]


@pytest.mark.parametrize("name,protocol", CASES)
def test_read_log_yields_the_cli_records(cli, logs, name, protocol):
    expected, rc, err = cli_json(cli, logs[name], *([protocol] if protocol else []))
    records = robowire.read_log(logs[name], protocol)
    assert list(records) == expected
    assert len(expected) > 0
    assert records.status == rc
    if rc != 2:  # the summary: "lines N, frames N, decoded N, errors N, ..."
        summary = err.strip().splitlines()[-1].split(": ")[-1]
        assert ", ".join(f"{k.replace('_', ' ')} {v}" for k, v in records.counters.items() if k != "input") == summary


def test_read_log_android_sample_by_hand(logs):
    # the header's date, midnight rollover, the error of line 6 among the messages
    records = list(robowire.read_log(logs["android.txt"]))
    assert [(r["type"], r["line"], r["time"], r.get("message")) for r in records] == [
        ("message", 5, "2026-03-15T00:00:00.100", "status"), ("error", 6, "2026-03-15T00:00:00.200", None),
        ("message", 7, "2026-03-15T00:00:00.300", "set_motor_data"),
        ("message", 8, "2026-03-15T00:00:00.400", "set_device_name")]
    assert records[0]["direction"] == "device_to_host" and records[0]["fields"]["battery_voltage"]["value"] == 13.0
    assert records[3]["fields"]["name"] == 'My,"B"'


def test_sample_session_figures(logs, tmp_path):
    # what docs/python.md says of the sample session
    records = robowire.read_log(logs["session.txt"])
    volts = [r["fields"]["battery_voltage"]["value"] for r in records if r.get("message") == "status"]
    assert len(volts) == 6000 and volts[0] == 12.5 and 10.4 <= volts[-1] <= 10.6
    assert {k: records.counters[k] for k in ("lines", "frames", "decoded", "errors")} == {
        "lines": 6018, "frames": 6011, "decoded": 6011, "errors": 0}
    assert robowire.to_csv(logs["session.txt"], tmp_path / "status.csv", message="status") == 6000


def test_read_log_file_objects(logs):
    expected = list(robowire.read_log(logs["session.txt"]))
    with open(logs["session.txt"], "rb") as fh:
        assert list(robowire.read_log(fh)) == expected
    with open(logs["session.txt"], "r") as fh:
        assert list(robowire.read_log(fh)) == expected
    assert list(robowire.read_log(io.BytesIO(logs["android.txt"].read_bytes()))) == list(robowire.read_log(logs["android.txt"]))


class CountingFile(io.BytesIO):
    def __init__(self, data):
        super().__init__(data)
        self.read_so_far = 0

    def read(self, n=-1):
        b = super().read(n)
        self.read_so_far += len(b)
        return b


def test_read_log_streams(logs):
    data = logs["10k.txt"].read_bytes()
    fh = CountingFile(data)
    records = robowire.read_log(fh)
    first = next(records)
    assert first["line"] == 7 and first["message"] == "set_data_period"  # before the first status
    assert fh.read_so_far <= 2 * 65536 < len(data) // 10, fh.read_so_far


def test_read_log_errors(tmp_path, logs):
    with pytest.raises(OSError, match="it is a directory"):
        robowire.read_log(tmp_path)
    with pytest.raises(OSError):
        robowire.read_log(tmp_path / "missing.txt")
    with pytest.raises(ValueError, match="unknown protocol 'bz3'"):
        robowire.read_log(logs["hex.txt"], "bz3")
    with pytest.raises(ValueError, match="since: '25:00' is no time"):
        robowire.read_log(logs["hex.txt"], "osp", since="25:00")
    with pytest.raises(TypeError, match="a path or a file object"):
        robowire.read_log(42)  # type: ignore[arg-type]
    records = list(robowire.read_log(logs["android.txt"], since="2026-03-15T00:00:00.200", until="00:00:00.300"))
    assert [r["line"] for r in records] == [6, 7]


@pytest.mark.parametrize("name,message,protocol", [("session.txt", "status", None), ("android.txt", "status", None),
                                                   ("android.txt", "set_device_name", None),
                                                   ("android.txt", "set_motor_data", "buwizz3"),
                                                   ("hex.txt", "voltage", "osp")])
def test_to_csv_is_the_cli_table(cli, logs, tmp_path, name, message, protocol):
    expected = cli_csv(cli, logs[name], message, *([protocol] if protocol else []))
    rows = expected.count("\n") - 1
    out = tmp_path / "out.csv"
    assert robowire.to_csv(logs[name], out, message=message, protocol=protocol) == rows
    assert out.read_text() == expected
    buf = io.StringIO()
    assert robowire.to_csv(robowire.read_log(logs[name], protocol), buf, message=message) == rows
    assert buf.getvalue() == expected


def test_csv_by_hand(logs):
    # the document's units: battery 9 V + 80 x 50 mV, currents raw x 15 mA, accel word x 0.488 mg
    buf = io.StringIO()
    robowire.to_csv(robowire.read_log(logs["android.txt"]), buf, message="status")
    head, row = (line.split(",") for line in buf.getvalue().splitlines())
    cells = dict(zip(head, row))
    assert head[:5] == ["time", "line", "direction", "flags", "battery_voltage[V]"]
    assert cells["battery_voltage[V]"] == "13" and cells["motor_current_5[A]"] == "3"
    assert cells["accel_0[mg]"] == "-7.808" and cells["pid_state.output"] == "12.75"
    assert robowire.csv_columns("buwizz3", "status")[11:15] == ["temperature_c[degC]", "accel_0[mg]", "accel_1[mg]",
                                                                "accel_2[mg]"]


def test_shortest_is_to_chars():
    # std::to_chars(double): the shortest digits, fixed or scientific, whichever is shorter (fixed on a tie)
    assert [_shortest(v) for v in (0.5, -2.5, 100.0, 1e20, 123456789012.0, 1e-05, 0.0001, 0.001, 1e15, 0.0, -0.0,
                                   1e16 + 2, 123456.5, 1e5)] == [
        "0.5", "-2.5", "100", "1e+20", "123456789012", "1e-05", "1e-04", "0.001", "1e+15", "0", "-0",
        "10000000000000002", "123456.5", "1e+05"]


def test_plot_draws_a_png(logs, tmp_path):
    pytest.importorskip("matplotlib")
    out = tmp_path / "session.png"
    drawn = robowire.plot(logs["session.txt"], ["battery_voltage", "motor_current"], out)
    assert drawn == {"message": "status", "points": 6000,
                     "columns": ["battery_voltage[V]"] + [f"motor_current_{i}[A]" for i in range(6)]}
    data = out.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n" and len(data) > 10000
    with pytest.raises(ValueError, match="unknown field battery_voltag: not in any message"):
        robowire.plot(logs["session.txt"], ["battery_voltag", "motor_current"], tmp_path / "x.png")


def test_python_m_robowire_plot(logs, tmp_path):
    pytest.importorskip("matplotlib")
    out = tmp_path / "out.png"
    p = subprocess.run([sys.executable, "-m", "robowire", "plot", str(logs["session.txt"]), "--fields",
                        "battery_voltage,motor_current", "-o", str(out)], capture_output=True, text=True, timeout=300)
    assert p.returncode == 0, p.stderr
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and out.stat().st_size > 0
    p = subprocess.run([sys.executable, "-m", "robowire", "plot", str(logs["session.txt"]), "--fields", "speed",
                        "-o", str(tmp_path / "y.png")], capture_output=True, text=True, timeout=300)
    assert p.returncode == 1 and p.stderr.startswith("error: unknown field speed") and not (tmp_path / "y.png").exists()


def test_plot_without_matplotlib(logs, tmp_path, monkeypatch):
    monkeypatch.setitem(sys.modules, "matplotlib", None)
    with pytest.raises(ImportError, match="python3-matplotlib"):
        robowire.plot(logs["android.txt"], ["battery_voltage"], tmp_path / "z.png")


@pytest.mark.parametrize("protocol", ["buwizz3", "navbot", "osp"])
def test_to_csv_from_records_every_vector(cli, tmp_path, protocol):
    # the golden vectors as hex lines: every message's table from records equals the tool's
    from vectors import CASES as VECTORS

    path = tmp_path / f"{protocol}.txt"
    path.write_text("".join(c[2] + "\n" for c in VECTORS if c[0] == protocol))
    records = list(robowire.read_log(path, protocol))
    messages = sorted({r["message"] for r in records if r["type"] == "message"})
    assert len(messages) >= 2
    for message in messages:
        buf = io.StringIO()
        robowire.to_csv(iter(records), buf, message=message)
        assert buf.getvalue() == cli_csv(cli, path, message, protocol), message
