# SPDX-License-Identifier: GPL-2.0-only
"""The counter character device (/dev/counterN) as its clients use it, the
kernel's tools/counter/counter_watch_events.c among them: watches added with
COUNTER_ADD_WATCH_IOCTL, events enabled with COUNTER_ENABLE_EVENTS_IOCTL,
struct counter_event read from the file (include/uapi/linux/counter.h,
Linux 5.16 on).  Guest library of drivers/pru_encoder's VM tests."""
import fcntl
import os
import select
import struct

# enum counter_component_type, enum counter_scope
COMPONENT_NONE, COMPONENT_SIGNAL, COMPONENT_COUNT = 0, 1, 2
SCOPE_DEVICE, SCOPE_SIGNAL, SCOPE_COUNT = 0, 1, 2
# enum counter_event_type
EVENT_OVERFLOW, EVENT_UNDERFLOW, EVENT_OVERFLOW_UNDERFLOW, EVENT_THRESHOLD = 0, 1, 2, 3
EVENT_INDEX, EVENT_CHANGE_OF_STATE, EVENT_CAPTURE = 4, 5, 6
EVENT_NAMES = {0: "overflow", 1: "underflow", 2: "overflow-underflow", 3: "threshold",
               4: "index", 5: "change-of-state", 6: "capture"}

# struct counter_watch: struct counter_component (type, scope, parent, id),
# event, channel: 6 bytes
WATCH = struct.Struct("=BBBBBB")
# struct counter_event: __aligned_u64 timestamp, __aligned_u64 value, struct
# counter_watch watch, __u8 status; 24 bytes with the padding
EVENT = struct.Struct("=QQBBBBBBBx")
assert EVENT.size == 24


def _ioc(direction, nr, size):
    return direction << 30 | size << 16 | 0x3E << 8 | nr


ADD_WATCH = _ioc(1, 0x00, WATCH.size)       # _IOW(0x3E, 0x00, struct counter_watch)
ENABLE_EVENTS = _ioc(0, 0x01, 0)            # _IO(0x3E, 0x01)
DISABLE_EVENTS = _ioc(0, 0x02, 0)           # _IO(0x3E, 0x02)


class Event:
    def __init__(self, raw):
        (self.timestamp, self.value, self.type, self.scope, self.parent, self.id,
         self.event, self.channel, self.status) = EVENT.unpack(raw)

    def __repr__(self):
        return "%s/%d value %d status %d" % (EVENT_NAMES.get(self.event, self.event),
                                             self.channel, self.value, self.status)


class Counter:
    """One open /dev/counterN."""

    def __init__(self, path, nonblock=False):
        self.fd = os.open(path, os.O_RDONLY | (os.O_NONBLOCK if nonblock else 0))

    def add_watch(self, event, channel, component=COMPONENT_COUNT, scope=SCOPE_COUNT,
                  parent=0, cid=0):
        """Queue a watch; the errno, 0 if it was accepted."""
        try:
            fcntl.ioctl(self.fd, ADD_WATCH, WATCH.pack(component, scope, parent, cid,
                                                       event, channel))
            return 0
        except OSError as e:
            return e.errno

    def enable(self):
        fcntl.ioctl(self.fd, ENABLE_EVENTS)

    def disable(self):
        fcntl.ioctl(self.fd, DISABLE_EVENTS)

    def read_events(self, timeout):
        """Events read within timeout seconds (one read, after a poll)."""
        r, _, _ = select.select([self.fd], [], [], timeout)
        if not r:
            return []
        data = os.read(self.fd, EVENT.size * 64)
        return [Event(data[i:i + EVENT.size]) for i in range(0, len(data), EVENT.size)]

    def read_blocking(self):
        """A blocking read: the events, or the OSError's errno."""
        try:
            data = os.read(self.fd, EVENT.size * 64)
        except OSError as e:
            return e.errno
        return [Event(data[i:i + EVENT.size]) for i in range(0, len(data), EVENT.size)]

    def close(self):
        if self.fd >= 0:
            os.close(self.fd)
            self.fd = -1
