"""Read the R, G, B channels of a scanline OpenEXR file as ochre writes it (uncompressed, ZIPS or ZIP; half or
float pixels), with numpy and no bpy: Blender 3.4's own loader into a render result crashes on an EXR with
more channels (spectral bins, light groups)."""
import struct
import zlib

import numpy as np

MAGIC = 20000630
LINES_PER_BLOCK = {0: 1, 2: 1, 3: 16}  # NONE, ZIPS, ZIP
BYTES = {1: 2, 2: 4}  # HALF, FLOAT
DTYPES = {1: '<f2', 2: '<f4'}


def _cstring(data, pos):
    end = data.index(b'\0', pos)
    return data[pos:end].decode('latin-1'), end + 1


def _header(data):
    if struct.unpack_from('<i', data, 0)[0] != MAGIC:
        raise ValueError('not an OpenEXR file')
    if data[5] & 0x1E:  # tiled, long names, deep or multi-part
        raise ValueError('only single-part scanline EXR files are read')
    pos, attrs = 8, {}
    while data[pos] != 0:
        name, pos = _cstring(data, pos)
        _, pos = _cstring(data, pos)
        size = struct.unpack_from('<i', data, pos)[0]
        attrs[name] = data[pos + 4:pos + 4 + size]
        pos += 4 + size
    return attrs, pos + 1


def _channels(raw):
    pos, out = 0, []
    while raw[pos] != 0:
        name, pos = _cstring(raw, pos)
        pixel_type, _, xs, ys = struct.unpack_from('<iB3xii', raw, pos)
        if xs != 1 or ys != 1 or pixel_type not in BYTES:
            raise ValueError(f'channel {name}: subsampled or integer channels are not read')
        out.append((name, pixel_type))
        pos += 16
    return sorted(out)


def _unzip(chunk, expected):
    if len(chunk) == expected:  # stored uncompressed when compressing did not pay
        return chunk
    t = np.frombuffer(zlib.decompress(chunk), dtype=np.uint8).astype(np.int64)
    t = (np.cumsum(np.concatenate(([t[0]], t[1:] - 128))) % 256).astype(np.uint8)  # undo the predictor
    half = (len(t) + 1) // 2
    out = np.empty_like(t)
    out[0::2], out[1::2] = t[:half], t[half:]
    return out.tobytes()


def channel_names(path):
    """The names of the file's channels, sorted."""
    with open(path, 'rb') as f:
        data = f.read()
    return [name for name, _ in _channels(_header(data)[0]['channels'])]


def read_rgb(path):
    """The image's R, G, B as a float32 array (height, width, 3), top row first."""
    with open(path, 'rb') as f:
        data = f.read()
    attrs, pos = _header(data)
    compression = attrs['compression'][0]
    if compression not in LINES_PER_BLOCK:
        raise ValueError(f'EXR compression {compression} is not read (uncompressed, ZIPS and ZIP are)')
    xmin, ymin, xmax, ymax = struct.unpack('<4i', attrs['dataWindow'])
    width, height = xmax - xmin + 1, ymax - ymin + 1
    channels = _channels(attrs['channels'])
    names = [c[0] for c in channels]
    if not {'R', 'G', 'B'} <= set(names):
        raise ValueError(f'no R, G, B channels (the file has {", ".join(names)})')
    lines = LINES_PER_BLOCK[compression]
    blocks = (height + lines - 1) // lines
    offsets = struct.unpack_from(f'<{blocks}Q', data, pos)
    line_bytes = sum(BYTES[t] for _, t in channels) * width
    rgb = np.zeros((height, width, 3), dtype=np.float32)
    for offset in offsets:
        y, size = struct.unpack_from('<ii', data, offset)
        n = min(lines, ymax + 1 - y)
        block = _unzip(data[offset + 8:offset + 8 + size], n * line_bytes) if compression else \
            data[offset + 8:offset + 8 + size]
        for row in range(n):
            at = row * line_bytes
            for name, pixel_type in channels:
                count = BYTES[pixel_type] * width
                if name in ('R', 'G', 'B'):
                    values = np.frombuffer(block, dtype=DTYPES[pixel_type], count=width, offset=at)
                    rgb[y - ymin + row, :, 'RGB'.index(name)] = values
                at += count
    return rgb
