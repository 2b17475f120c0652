// Chromium's MediaRecorder writes WebM without a duration (it streams), so players show none and
// cannot seek. This writes Segment > Info > Duration (EBML id 0x4489, a float64 in timecode-scale
// units) into the recorded bytes once the length is known.
const SEGMENT = 0x18538067;
const INFO = 0x1549a966;
const DURATION = 0x4489;
const TIMECODE_SCALE = 0x2ad7b1;

function vintLength(first) {
  for (let n = 1; n <= 8; n++) if (first & (0x80 >> (n - 1))) return n;
  throw new Error('not an EBML variable-length integer');
}

/// {value, length}; keepMarker for element ids, which keep their length marker.
function readVint(bytes, at, keepMarker) {
  const length = vintLength(bytes[at]);
  let value = keepMarker ? bytes[at] : bytes[at] & (0xff >> length);
  let unknown = value === (0xff >> length);
  for (let i = 1; i < length; i++) {
    value = value * 256 + bytes[at + i];
    unknown = unknown && bytes[at + i] === 0xff;
  }
  return { value, length, unknown: !keepMarker && unknown };
}

/// A size as an 8-byte vint (always valid, whatever the size was written with before).
function sizeBytes(size) {
  const out = new Uint8Array(8);
  out[0] = 0x01;
  for (let i = 7, v = size; i >= 1; i--, v = Math.floor(v / 256)) out[i] = v % 256;
  return out;
}

function readElement(bytes, at) {
  const id = readVint(bytes, at, true);
  const size = readVint(bytes, at + id.length, false);
  const dataStart = at + id.length + size.length;
  return { id: id.value, dataStart, size: size.unknown ? null : size.value, end: size.unknown ? bytes.length : dataStart + size.value };
}

/// The WebM with its duration set to `ms` milliseconds (unchanged if it has no Info element).
export function withDuration(buffer, ms) {
  const bytes = new Uint8Array(buffer);
  const header = readElement(bytes, 0);
  const segment = readElement(bytes, header.end);
  if (segment.id !== SEGMENT) return bytes;
  for (let at = segment.dataStart; at < segment.end;) {
    const child = readElement(bytes, at);
    if (child.id !== INFO) { at = child.end; continue; }
    let scale = 1000000;
    const kept = [];
    for (let c = child.dataStart; c < child.end;) {
      const item = readElement(bytes, c);
      if (item.id === TIMECODE_SCALE) { scale = 0; for (let i = item.dataStart; i < item.end; i++) scale = scale * 256 + bytes[i]; }
      if (item.id !== DURATION) kept.push(bytes.subarray(c, item.end));
      c = item.end;
    }
    const duration = new Uint8Array(11);
    duration.set([0x44, 0x89, 0x88]);  // id, size 8
    new DataView(duration.buffer).setFloat64(3, (ms * 1e6) / scale);
    const body = [...kept, duration];
    const bodySize = body.reduce((n, b) => n + b.length, 0);
    const infoId = bytes.subarray(at, at + readVint(bytes, at, true).length);
    const parts = [bytes.subarray(0, at), infoId, sizeBytes(bodySize), ...body, bytes.subarray(child.end)];
    const out = new Uint8Array(parts.reduce((n, p) => n + p.length, 0));
    let o = 0;
    for (const p of parts) { out.set(p, o); o += p.length; }
    if (segment.size === null) return out;
    // A segment of known size grows by what Info grew by: rewrite its size field.
    const grown = out.length - bytes.length;
    const segIdLength = readVint(bytes, header.end, true).length;
    const segSizeAt = header.end + segIdLength;
    const segSizeLength = readVint(bytes, segSizeAt, false).length;
    const fixed = [out.subarray(0, segSizeAt), sizeBytes(segment.size + grown), out.subarray(segSizeAt + segSizeLength)];
    const result = new Uint8Array(fixed.reduce((n, p) => n + p.length, 0));
    o = 0;
    for (const p of fixed) { result.set(p, o); o += p.length; }
    return result;
  }
  return bytes;
}
