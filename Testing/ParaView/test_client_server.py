"""Client-server: a pvserver of two MPI ranks on the loopback interface, a pvpython client that
loads the plugin on both sides and compares every proxy's remote output with the built-in
connection's (client_server_compare.py).

Run with /usr/bin/python3. The server listens on a free port of 127.0.0.1 that the client reaches
as 'localhost'; pvserver has no option to bind one address, so as root the whole test runs in a
network namespace of its own (`unshare --net`, only `lo` up) and the server is reachable from
nowhere else. Every wait is bounded, and the server's process group is killed at the end, whatever
happened.
"""
import argparse
import os
import signal
import socket
import subprocess
import sys
import threading
import time

HERE = os.path.dirname(os.path.abspath(__file__))
IN_NAMESPACE = "BOOSTEDSURFACES_TEST_NETNS"
SERVER_START_SECONDS = 90
CLIENT_SECONDS = 180
SERVER_EXIT_SECONDS = 20


def parse_arguments():
    parser = argparse.ArgumentParser()
    parser.add_argument("--pvserver", required=True)
    parser.add_argument("--pvpython", required=True)
    parser.add_argument("--mpiexec", required=True)
    parser.add_argument("--mpiexec-flags", default="", help="e.g. --allow-run-as-root, space-separated")
    parser.add_argument("--plugin", required=True, help="path of BoostedSurfaces.so")
    return parser.parse_args()


def in_own_network_namespace():
    """As root with unshare and ip at hand, run this script again in a new network namespace with
    only the loopback interface; otherwise go on here (the server then also listens on the other
    interfaces, but nothing but loopback is used)."""
    if os.environ.get(IN_NAMESPACE) or os.geteuid() != 0:
        return False
    probe = subprocess.run(["unshare", "--net", "true"], capture_output=True)
    if probe.returncode != 0:
        print("unshare --net is not available here (%s); running on the host's loopback"
              % probe.stderr.decode().strip())
        return False
    environment = dict(os.environ, **{IN_NAMESPACE: "1"})
    command = ["unshare", "--net", "--", "sh", "-c", 'ip link set lo up && exec "$@"', "sh",
               sys.executable] + sys.argv
    return subprocess.run(command, env=environment).returncode


def free_loopback_port():
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as probe:
        probe.bind(("127.0.0.1", 0))
        return probe.getsockname()[1]


def start_server(arguments, port):
    """mpiexec -np 2 pvserver in its own process group; returns it once it accepts connections."""
    command = ([arguments.mpiexec] + arguments.mpiexec_flags.split() +
               ["-np", "2", arguments.pvserver, "--server-port=%d" % port,
                "--force-offscreen-rendering", "--disable-xdisplay-test"])
    print("server:", " ".join(command), flush=True)
    # errors="replace": a byte that is not UTF-8 would end the echo thread (below) with a
    # UnicodeDecodeError, hiding the rest of the server's output and its readiness.
    server = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                              start_new_session=True, text=True, errors="replace")
    ready = threading.Event()

    def echo():  # the server's output, prefixed; it says when it accepts connections
        for line in server.stdout:
            print("[pvserver] " + line.rstrip(), flush=True)
            if "Accepting connection" in line:
                ready.set()
    threading.Thread(target=echo, daemon=True).start()
    deadline = time.monotonic() + SERVER_START_SECONDS
    while not ready.wait(0.2):
        if server.poll() is not None or time.monotonic() > deadline:
            raise RuntimeError("pvserver did not start accepting connections within %d s"
                               % SERVER_START_SECONDS)
    return server


def stop_server(server):
    """Wait a little for the server to leave on its own (it does when its client disconnects),
    then kill its whole process group (mpiexec and both ranks)."""
    try:
        server.wait(SERVER_EXIT_SECONDS)
    except subprocess.TimeoutExpired:
        print("pvserver still running after %d s; killing it" % SERVER_EXIT_SECONDS)
    try:
        os.killpg(server.pid, signal.SIGKILL)
    except ProcessLookupError:
        pass
    server.wait()


def main():
    arguments = parse_arguments()
    status = in_own_network_namespace()
    if status is not False:
        return status
    port = free_loopback_port()
    server = start_server(arguments, port)
    try:
        client = subprocess.run(
            [arguments.pvpython, "--force-offscreen-rendering",
             os.path.join(HERE, "client_server_compare.py"),
             "--plugin", arguments.plugin, "--port", str(port)], timeout=CLIENT_SECONDS)
        return client.returncode
    finally:
        stop_server(server)


if __name__ == "__main__":
    sys.exit(main())
