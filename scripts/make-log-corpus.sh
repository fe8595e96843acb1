#!/usr/bin/env bash
# Records the log reader's seed corpus (fixtures/logs/corpus, described in tests/fuzz/README.md)
# again with a gizmo binary: the valid logs, then the broken ones cut or edited from them.
# Run it when the log format changes: scripts/make-log-corpus.sh build/release/cli/gizmo
set -euo pipefail
gizmo=$(realpath "${1:?usage: $0 GIZMO_BINARY}")
root=$(cd "$(dirname "$0")/.." && pwd)
out=$root/fixtures/logs/corpus
spec=fixtures/boards/spec-example.txt  # paths from the root: board warnings in a log name the file as given
rm -f "$out"/*.gzlog

record() {  # NAME BOARD ARGS...
  local name=$1 board=$2
  shift 2
  (cd "$root" && "$gizmo" record "$board" -o "$out/$name.gzlog" "$@" > /dev/null 2>&1)
}
record spec-double-0.2s "$spec" --time 0.2
record spec-double-1s "$spec" --time 1
record spec-classic-1s "$spec" --time 1 --model classic
record spec-float-0.2s "$spec" --time 0.2 --precision float
record spec-long-double-0.2s "$spec" --time 0.2 --precision long-double
record spec-float128-0.1s "$spec" --time 0.1 --precision float128
record spec-mpfr128-0.1s "$spec" --time 0.1 --precision mpfr:128
record spec-flipper-keys-1s "$spec" --time 1 --keys "$root/fixtures/keys/flippers.keys"
record four-balls-meeting-5s fixtures/boards/scenes/four-balls-meeting.txt --time 5
# A board read leniently: the log's header lists its warnings (since format 3).
record lenient-board-1s fixtures/boards/lenient/spec-example-messy.txt --time 1

# The broken ones. A log is a 12-byte file header, frames (u8 type, u32 length, payload, u64
# checksum) and a 16-byte trailer (docs/replay-format.md).
python3 - "$out" <<'EOF'
import struct, sys
out = sys.argv[1]

def load(name):
    return bytearray(open(f"{out}/{name}.gzlog", "rb").read())

def save(name, data):
    open(f"{out}/broken-{name}.gzlog", "wb").write(bytes(data))

def frames(data):  # (offset, type, payload length) of each frame
    at, found = 12, []
    while at + 5 <= len(data) - 16:
        kind, length = data[at], struct.unpack_from("<I", data, at + 1)[0]
        found.append((at, chr(kind), length))
        at += 5 + length + 8
    return found

log = load("spec-double-0.2s")
header, chunk = frames(log)[0], frames(log)[1]
save("cut-inside-header", log[: header[0] + 5 + header[2] // 2])
keys = load("spec-flipper-keys-1s")
keys_chunk = frames(keys)[1]
save("cut-inside-chunk", keys[: keys_chunk[0] + 5 + keys_chunk[2] // 2])
save("cut-inside-trailer", log[:-8])
damaged = bytearray(log)
damaged[-1] ^= 0xFF
save("damaged-trailer", damaged)
flipped = bytearray(log)
flipped[chunk[0] + 5 + chunk[2] - 1] ^= 0x01  # the chunk's last record byte
save("flipped-record-byte", flipped)
newer = bytearray(log)
struct.pack_into("<H", newer, 8, struct.unpack_from("<H", newer, 8)[0] + 1)
save("newer-version", newer)
magic = bytearray(log)
magic[0] ^= 0x20
save("wrong-magic", magic)
EOF
ls -l "$out"
