"""The layout of checkpoint.bin, format 4 (doc/decisions.md D160), read by
an implementation independent of deepdraw's: the fields' byte ranges, so
that a test can change one field and seal the image again with a CRC-32
computed here (crc32 below, checked against zlib's), and so test the range
checks behind the checksum rather than the checksum.

    image = CheckpointImage(path.read_bytes())
    image.replace("next_increment", struct.pack("<d", 0.0))
    path.write_bytes(image.sealed())
"""
import struct
import zlib

TAG = b"deepdraw-checkpoint-4\0"
STATE_TAG = b"deepdraw-state-5\0"
# fe::EnhancedParameters: 9 + 24 + 9 + 9 * 24 doubles.
ENHANCED_BYTES = 8 * (9 + 24 + 9 + 9 * 24)


def _crc_table():
    table = []
    for i in range(256):
        c = i
        for _ in range(8):
            c = (0xEDB88320 ^ (c >> 1)) if c & 1 else c >> 1
        table.append(c)
    return table


_TABLE = _crc_table()


def crc32(data):
    """CRC-32 (IEEE, reflected 0xEDB88320), written out here."""
    c = 0xFFFFFFFF
    for byte in data:
        c = _TABLE[(c ^ byte) & 0xFF] ^ (c >> 8)
    return c ^ 0xFFFFFFFF


assert crc32(b"123456789") == 0xCBF43926 == zlib.crc32(b"123456789")


class CheckpointImage:
    """The fields of a format-4 image: self.fields[name] = (start, end),
    byte ranges of the content (the CRC-32 is the last 4 bytes)."""

    def __init__(self, data):
        if not data.startswith(TAG):
            raise ValueError("not a format-4 checkpoint")
        self.data = bytearray(data[:-4])
        self.stored_crc = struct.unpack("<I", data[-4:])[0]
        self.fields = {}
        self.position = len(TAG)
        self._parse()
        if self.position != len(self.data):
            raise ValueError("%d bytes left after the last field"
                             % (len(self.data) - self.position))

    def check_crc(self):
        """Whether deepdraw's stored CRC-32 equals the one computed here."""
        return crc32(bytes(self.data)) == self.stored_crc

    def _take(self, name, size):
        self.fields[name] = (self.position, self.position + size)
        self.position += size
        return bytes(self.data[self.position - size:self.position])

    def _count(self, name):
        return struct.unpack("<Q", self._take(name, 8))[0]

    def _block(self, name, element_size):
        n = self._count(name + ".count")
        self._take(name, n * element_size)
        return n

    def _string(self, name):
        n = self._count(name + ".size")
        return self._take(name, n).decode("utf-8", "replace")

    def _parse(self):
        self._string("parameters")
        if self._take("state.tag", len(STATE_TAG)) != STATE_TAG:
            raise ValueError("not a state of format 5")
        self._take("load", 8)
        self._take("last_load_increment", 8)
        self._take("increment_number", 4)
        for name in ("vertices", "total_displacement", "converged_solution",
                     "previous_converged_solution", "history"):
            self._block(name, 8)
        self._block("enhanced_parameters", ENHANCED_BYTES)
        self._take("next_increment", 8)
        self._block("pair_open", 1)
        self._block("pair_status", 1)
        self._block("tool_position", 8)
        for cycle in range(self._count("refinements.count")):
            self._block("refinement_%d" % cycle, 12)
        self._take("stage", 4)
        self._take("stage_completed", 1)
        self._take("stage_force_scale", 8)
        self._block("tool_origin", 8)
        self._block("tool_translation", 8)
        self._take("end_force_scale", 8)
        self._block("release_loads", 8)
        self._block("release_support_vertices", 4)
        self._block("release_start_displacement", 8)
        self.tables = []
        for i in range(self._count("tables.count")):
            name = self._string("table_%d.name" % i)
            size = struct.unpack("<Q", self._take("table_%d.bytes" % i, 8))[0]
            self.tables.append((name, size))
        for i in range(self._count("postprocessors.count")):
            self._string("postprocessor_%d.name" % i)
            self._string("postprocessor_%d.data" % i)
        self.input_files = []
        for i in range(self._count("input_files.count")):
            parameter = self._string("input_%d.parameter" % i)
            path = self._string("input_%d.path" % i)
            self._take("input_%d.size" % i, 8)
            self._take("input_%d.crc" % i, 4)
            self.input_files.append((parameter, path))

    def table_index(self, name):
        return [t[0] for t in self.tables].index(name)

    def replace(self, field, new_bytes):
        """Replaces a field's bytes (the same length)."""
        start, end = self.fields[field]
        if len(new_bytes) != end - start:
            raise ValueError("%s has %d bytes" % (field, end - start))
        self.data[start:end] = new_bytes

    def replace_string(self, field, text):
        """Replaces a text field (its size and bytes); the fields after it
        move, so the image is parsed again."""
        size_start = self.fields[field + ".size"][0]
        end = self.fields[field][1]
        encoded = text.encode()
        self.data[size_start:end] = struct.pack("<Q", len(encoded)) + encoded
        self.__init__(self.sealed())

    def double(self, field):
        return struct.unpack("<d", bytes(self.data[slice(*self.fields[field])]))[0]

    def sealed(self):
        """The image with a CRC-32 of its content, computed here."""
        return bytes(self.data) + struct.pack("<I", crc32(bytes(self.data)))

    def unsealed(self):
        """The image with the CRC-32 deepdraw stored (now wrong if a field
        was changed)."""
        return bytes(self.data) + struct.pack("<I", self.stored_crc)

    def as_format_3(self):
        """The same checkpoint in format 3: no input files, no checksum."""
        end = self.fields["input_files.count"][0]
        return b"deepdraw-checkpoint-3\0" + bytes(self.data[len(TAG):end])
