"""solve(case, out=...) and its folder: one run at a time (a second solve into a folder another
process is writing is refused at once with InputError naming the folder; the lock goes with the
call), and a file that cannot be written is OutputError (an OSError naming the file), with no cut
summary.json."""
import errno
import fcntl
import json
import os
import resource
import signal
import subprocess
import sys
import time

import pytest

import dyncontact

from example_cases import example


def hertz(nx):
    case = example("hertz-sphere")
    case["grid"] = {"nx": nx, "ny": nx, "extent": 1.5}
    return case


def test_a_second_solve_into_a_folder_another_process_writes_is_refused(tmp_path):
    out = tmp_path / "out"
    lock = out / ".dyncontact.lock"
    code = "import dyncontact, json, sys; dyncontact.solve(json.loads(sys.argv[1]), out=sys.argv[2])"
    first = subprocess.Popen([sys.executable, "-c", code, json.dumps(hertz(192)), str(out)],
                             stderr=subprocess.PIPE, text=True)
    try:
        # Held (SIGSTOP) once it has locked the folder (it writes its pid there), so the second
        # solve surely meets it whatever the machine's load.
        deadline = time.monotonic() + 120
        while not (lock.exists() and lock.read_text() == f"{first.pid}\n"):
            assert first.poll() is None, "the first solve ended before it locked the folder: " + first.stderr.read()
            assert time.monotonic() < deadline
            time.sleep(0.002)
        os.kill(first.pid, signal.SIGSTOP)
        with pytest.raises(dyncontact.InputError) as refused:
            dyncontact.solve(hertz(16), out=out)
        os.kill(first.pid, signal.SIGCONT)
        assert refused.value.key == "out"
        assert f"'{out}'" in str(refused.value) and "in use" in str(refused.value)
        assert first.wait(timeout=300) == 0
    finally:
        if first.poll() is None:
            os.kill(first.pid, signal.SIGCONT)
            first.kill()
            first.wait()
    # The folder holds the first run's files: summary and fields of its 192 x 192 grid.
    summary = json.loads((out / "summary.json").read_text())
    assert summary["grid"]["nx"] == 192
    assert len((out / "fields.csv").read_text().splitlines()) == 1 + 192 * 192
    # After the first process, a solve into the folder works, and its lock goes with the call.
    assert dyncontact.solve(hertz(16), out=out)["grid"]["nx"] == 16
    with open(lock) as f:
        fcntl.flock(f, fcntl.LOCK_EX | fcntl.LOCK_NB)


def test_a_file_that_cannot_be_written_is_output_error(tmp_path):
    out = tmp_path / "out"
    soft, hard = resource.getrlimit(resource.RLIMIT_FSIZE)
    # 10 kB: fields.csv of 64 x 64 elements (about 200 kB) does not fit (Python ignores SIGXFSZ:
    # the write fails with EFBIG).
    resource.setrlimit(resource.RLIMIT_FSIZE, (10000, hard))
    try:
        with pytest.raises(dyncontact.OutputError) as failed:
            dyncontact.solve(hertz(64), out=out)
    finally:
        resource.setrlimit(resource.RLIMIT_FSIZE, (soft, hard))
    assert isinstance(failed.value, OSError)
    assert failed.value.errno == errno.EFBIG
    assert failed.value.filename == str(out / "fields.csv")
    assert not (out / "summary.json").exists()
    assert not [p for p in os.listdir(out) if p.startswith(".partial-")]
