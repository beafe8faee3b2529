"""A real single-host Slurm cluster for tests: munged, slurmctld and slurmd on 127.0.0.1, from a
generated slurm.conf in a temporary folder (its own munge key, socket, pid and log files, state
and spool folders, free ports), no accounting. Used as a context manager; every daemon is
stopped by its pid when the block ends, also on failure."""

import ctypes
import os
import shutil
import signal
import socket
import subprocess
import time

BINARIES = ["munged", "slurmctld", "slurmd", "sbatch", "squeue", "sinfo", "scontrol"]
NODE = "gonio0"


def missing_binaries():
    return [b for b in BINARIES if shutil.which(b) is None]


def die_with_parent():
    """In a daemon's child process before exec: SIGTERM when the test itself dies, even by
    SIGKILL (a ctest timeout), so that no daemon outlives it."""
    PR_SET_PDEATHSIG = 1
    ctypes.CDLL(None, use_errno=True).prctl(PR_SET_PDEATHSIG, signal.SIGTERM)


def free_port():
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def memory_mb():
    with open("/proc/meminfo") as f:
        for line in f:
            if line.startswith("MemTotal:"):
                # Below the total: slurmd drains a node that has less than it is said to have.
                return int(line.split()[1]) // 1024 * 9 // 10
    return 1024


class SlurmCluster:
    def __init__(self, folder, cpus=None):
        self.dir = os.path.abspath(folder)
        self.cpus = cpus or os.cpu_count()
        self.procs = []
        self.conf = os.path.join(self.dir, "slurm.conf")
        self.env = dict(os.environ, SLURM_CONF=self.conf)

    def path(self, name):
        return os.path.join(self.dir, name)

    def write_config(self):
        for d in ["state", "spool", "munge"]:
            os.makedirs(self.path(d), exist_ok=True)
        os.chmod(self.path("munge"), 0o700)
        key = self.path("munge/munge.key")
        with open(key, "wb") as f:
            f.write(os.urandom(1024))
        os.chmod(key, 0o400)
        host = socket.gethostname().split(".")[0]
        lines = [
            "ClusterName=gonio-test",
            # slurmctld only runs on a host its SlurmctldHost names; the address is loopback.
            f"SlurmctldHost={host}(127.0.0.1)",
            f"SlurmctldPort={free_port()}",
            f"SlurmdPort={free_port()}",
            "SlurmUser=root",
            "SlurmdUser=root",
            f"AuthInfo=socket={self.path('munge/munge.socket')}",
            "AuthType=auth/munge",
            "CredType=cred/munge",
            f"StateSaveLocation={self.path('state')}",
            f"SlurmdSpoolDir={self.path('spool')}",
            f"SlurmctldPidFile={self.path('slurmctld.pid')}",
            f"SlurmdPidFile={self.path('slurmd.pid')}",
            f"SlurmctldLogFile={self.path('slurmctld.log')}",
            f"SlurmdLogFile={self.path('slurmd.log')}",
            "ProctrackType=proctrack/linuxproc",
            "TaskPlugin=task/none",
            "SelectType=select/cons_tres",
            "SelectTypeParameters=CR_CPU",
            "SchedulerType=sched/backfill",
            "AccountingStorageType=accounting_storage/none",
            "JobAcctGatherType=jobacct_gather/none",
            "JobCompType=jobcomp/none",
            "MpiDefault=none",
            "ReturnToService=2",
            "SlurmctldTimeout=30",
            "SlurmdTimeout=30",
            "MinJobAge=300",
            f"NodeName={NODE} NodeHostname={host} NodeAddr=127.0.0.1 CPUs={self.cpus} "
            f"RealMemory={memory_mb()} State=UNKNOWN",
            f"PartitionName=test Nodes={NODE} Default=YES MaxTime=INFINITE State=UP",
        ]
        with open(self.conf, "w") as f:
            f.write("\n".join(lines) + "\n")

    def start(self, name, argv):
        log = open(self.path(name + ".out"), "w")
        proc = subprocess.Popen(argv, stdout=log, stderr=subprocess.STDOUT, env=self.env,
                                preexec_fn=die_with_parent)
        self.procs.append((name, proc))
        return proc

    def wait_for(self, what, check, seconds=30):
        deadline = time.time() + seconds
        while time.time() < deadline:
            for name, proc in self.procs:
                if proc.poll() is not None:
                    raise RuntimeError(f"{name} exited ({proc.returncode}) while waiting for "
                                       f"{what}:\n{self.logs()}")
            if check():
                return
            time.sleep(0.2)
        raise RuntimeError(f"timed out waiting for {what}:\n{self.logs()}")

    def logs(self):
        text = ""
        for name in ["munged.log", "munged.out", "slurmctld.log", "slurmctld.out", "slurmd.log",
                     "slurmd.out"]:
            p = self.path(name)
            if os.path.exists(p):
                with open(p, errors="replace") as f:
                    text += f"--- {name} (last lines)\n" + "".join(f.readlines()[-15:])
        return text

    def node_state(self):
        r = subprocess.run(["sinfo", "-h", "-N", "-o", "%T"], env=self.env,
                           capture_output=True, text=True)
        return r.stdout.strip() if r.returncode == 0 else ""

    def __enter__(self):
        self.write_config()
        munge = self.path("munge")
        self.start("munged", ["munged", "--foreground", "--force",
                              f"--key-file={munge}/munge.key", f"--socket={munge}/munge.socket",
                              f"--pid-file={munge}/munged.pid", f"--log-file={self.path('munged.log')}",
                              f"--seed-file={munge}/munged.seed"])
        self.wait_for("munged's socket", lambda: os.path.exists(f"{munge}/munge.socket"))
        self.start("slurmctld", ["slurmctld", "-D", "-i", "-f", self.conf])
        self.start("slurmd", ["slurmd", "-D", "-f", self.conf, "-N", NODE])
        self.wait_for("the node to be idle", lambda: self.node_state() == "idle", 60)
        return self

    def __exit__(self, *exc):
        self.stop()
        return False

    def stop(self):
        # slurmd first (it kills its jobs' steps), then the controller, then munge; by pid.
        for name, proc in reversed(self.procs):
            if proc.poll() is None:
                proc.send_signal(signal.SIGTERM)
                try:
                    proc.wait(10)
                except subprocess.TimeoutExpired:
                    proc.kill()
                    proc.wait()
        self.procs = []
