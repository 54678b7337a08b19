# SPDX-License-Identifier: GPL-2.0-only
"""The prukit command in the guest (/usr/bin/prukit, make tool_install), run
as root or as an unprivileged user, for the VM tests of its subcommands
(tests/vm/cases/87-prukit-ws281x, 88-prukit-hub75, 89-prukit-capture)."""
import grp
import os
import subprocess

from rpmsg import info

PRUKIT = "/usr/bin/prukit"


class Result:
    """What a run of prukit did: rc, out, err, and the command line."""

    def __init__(self, argv, rc, out, err):
        self.argv, self.rc, self.out, self.err = argv, rc, out, err

    def __str__(self):
        return "prukit %s: exit %d; stderr: %s; stdout: %s" % (
            " ".join(self.argv), self.rc, self.err.strip()[-600:], self.out.strip()[-300:])

    def clean_error(self, *want):
        """A failure as the command reports one: exit 1, "prukit: error:"
        and every text of WANT on stderr, no Python traceback."""
        return (self.rc == 1 and self.err.startswith("prukit: error: ") and
                "Traceback" not in self.err + self.out and all(w in self.err for w in want))

    def usage_error(self, *want):
        """An argparse error: exit 2, the usage, every text of WANT."""
        return (self.rc == 2 and "usage: prukit" in self.err and "Traceback" not in self.err and
                all(w in self.err for w in want))


def prukit(*argv, uid=None, groups=(), timeout=600):
    """Run prukit ARGV (as UID with only the supplementary GROUPS, names,
    when UID is given); its Result."""
    kw = {}
    if uid is not None:
        gids = [grp.getgrnam(g).gr_gid for g in groups]
        kw = dict(user=uid, group=gids[0] if gids else 65534, extra_groups=gids)
    env = dict(os.environ, LANG="C.UTF-8", PYTHONDONTWRITEBYTECODE="1")
    r = subprocess.run([PRUKIT] + list(argv), capture_output=True, encoding="utf-8", errors="replace",
                       timeout=timeout, env=env, cwd="/", **kw)
    res = Result(list(argv), r.returncode, r.stdout, r.stderr)
    if r.returncode:
        info("prukit %s: exit %d: %s" % (" ".join(argv), r.returncode,
                                         " | ".join(r.stderr.strip().splitlines()[:8])))
    return res
