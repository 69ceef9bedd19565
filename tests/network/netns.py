"""Three "hosts" on one machine for the network tests: Linux network namespaces joined by veth
pairs to a bridge in a fourth namespace (the switch), so that nothing of the machine's own
network changes and deleting the namespaces removes everything. Faults as on a real network
(../shared/docs/reliability-tests.md, fact 8): a silent partition (nftables policy drop),
packet loss (nftables numgen), a bandwidth limit (tc tbf), a link down and up. Needs root,
iproute2 and nftables."""

import subprocess

SUBNET = "10.77.0"


def sh(*command, check=True):
    return subprocess.run(list(command), stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True, check=check)


def available():
    """Why the namespaces cannot be made here, or None."""
    import os
    import shutil
    if os.geteuid() != 0:
        return "not root"
    for tool in ("ip", "nft", "tc"):
        if not shutil.which(tool):
            return "%s not installed" % tool
    probe = sh("ip", "netns", "add", "fsi-probe", check=False)
    if probe.returncode != 0:
        return "cannot make network namespaces: " + probe.stdout.strip()
    sh("ip", "netns", "del", "fsi-probe", check=False)
    return None


class Network:
    """Hosts by name ("coupler", "structure", "fluid"), each a namespace fsi<pid>-<name> with one
    interface eth0 at SUBNET.<2..>."""

    def __init__(self, hosts):
        import os
        self.prefix_name = "fsi%d-" % os.getpid()  # several test processes at once: their own names
        self.hosts = list(hosts)
        self.address = {h: "%s.%d" % (SUBNET, i + 2) for i, h in enumerate(self.hosts)}
        self.destroy()
        switch = self.namespace("switch")
        sh("ip", "netns", "add", switch)
        sh("ip", "-n", switch, "link", "add", "br0", "type", "bridge")
        sh("ip", "-n", switch, "link", "set", "br0", "up")
        for host in self.hosts:
            ns = self.namespace(host)
            sh("ip", "netns", "add", ns)
            sh("ip", "-n", ns, "link", "set", "lo", "up")
            port = "p-" + host[:10]
            sh("ip", "-n", ns, "link", "add", "eth0", "type", "veth", "peer", "name", port, "netns", switch)
            sh("ip", "-n", ns, "addr", "add", self.address[host] + "/24", "dev", "eth0")
            sh("ip", "-n", ns, "link", "set", "eth0", "up")
            sh("ip", "-n", switch, "link", "set", port, "master", "br0")
            sh("ip", "-n", switch, "link", "set", port, "up")

    def namespace(self, host):
        return self.prefix_name + host

    def destroy(self):
        listed = sh("ip", "netns", "list", check=False).stdout
        for line in listed.splitlines():
            name = line.split()[0] if line.split() else ""
            if name.startswith(self.prefix_name):
                sh("ip", "netns", "del", name, check=False)

    def prefix(self, host):
        """The command prefix that runs a program on `host`."""
        return ["ip", "netns", "exec", self.namespace(host)]

    def run(self, host, *command):
        return sh(*(self.prefix(host) + list(command)))

    # ---- faults -------------------------------------------------------------------------

    def partition(self, host):
        """Silently drops everything to and from `host` (no reset, no ICMP: a dead link)."""
        self.run(host, "nft", "add table inet fsi_fault; "
                 "add chain inet fsi_fault in { type filter hook input priority 0; policy drop; }; "
                 "add chain inet fsi_fault out { type filter hook output priority 0; policy drop; }; "
                 "add rule inet fsi_fault in iifname lo accept; add rule inet fsi_fault out oifname lo accept")

    def lose(self, host, percent):
        """Drops `percent` % of the packets in each direction at `host`, at random."""
        self.run(host, "nft", "add table inet fsi_fault; "
                 "add chain inet fsi_fault in { type filter hook input priority 0; policy accept; }; "
                 "add chain inet fsi_fault out { type filter hook output priority 0; policy accept; }; "
                 "add rule inet fsi_fault in iifname eth0 numgen random mod 100 < %d drop; "
                 "add rule inet fsi_fault out oifname eth0 numgen random mod 100 < %d drop" % (percent, percent))

    def limit_rate(self, host, rate="10mbit"):
        self.run(host, "tc", "qdisc", "add", "dev", "eth0", "root", "tbf", "rate", rate, "burst", "32kbit",
                 "latency", "400ms")

    def heal(self, host):
        self.run(host, "nft", "delete table inet fsi_fault")

    def link(self, host, up):
        self.run(host, "ip", "link", "set", "eth0", "up" if up else "down")
