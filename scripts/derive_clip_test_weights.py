#!/usr/bin/env python3
"""Derives tests/fixtures/clip/models/<name>/weights_rows.safetensors from the shared reference
fixture weights.safetensors (float32) to keep the repository small: identical tensors, except that
token_embedding.weight [49408, W] (75% of the file) is replaced by the rows the fixture's tokens.npy
uses: token_embedding.weight.ids [K] (I64) and token_embedding.weight.rows [K, W] (F32). No other
row can influence any fixture output (the embedding is a lookup), so tests rebuild the full matrix
with zeros elsewhere. Standard library only.
Run: python3 scripts/derive_clip_test_weights.py /work/shared/fixtures/clip/models/tiny_gelu \
         tests/fixtures/clip/models/tiny_gelu"""
import ast, json, struct, sys

def read_safetensors(path):
    data = open(path, 'rb').read()
    n = struct.unpack('<Q', data[:8])[0]
    header = json.loads(data[8:8 + n])
    return header, data[8 + n:]

def read_npy_int64(path):
    data = open(path, 'rb').read()
    assert data[:6] == b'\x93NUMPY'
    hlen = struct.unpack('<H', data[8:10])[0]
    h = ast.literal_eval(data[10:10 + hlen].decode('latin-1'))
    assert h['descr'] == '<i8' and not h['fortran_order']
    count = 1
    for s in h['shape']:
        count *= s
    return list(struct.unpack('<%dq' % count, data[10 + hlen:10 + hlen + 8 * count]))

def main(src, dst):
    header, buf = read_safetensors(src + '/weights.safetensors')
    ids = sorted(set(read_npy_int64(src + '/tokens.npy')))
    meta = header.pop('__metadata__', {})
    entries = []  # (name, dtype, shape, bytes) in file order
    for name, info in sorted(header.items(), key=lambda kv: kv[1]['data_offsets'][0]):
        b, e = info['data_offsets']
        raw = buf[b:e]
        if name == 'token_embedding.weight':
            vocab, width = info['shape']
            row = 4 * width
            rows = b''.join(raw[i * row:(i + 1) * row] for i in ids)
            entries.append((name + '.ids', 'I64', [len(ids)], struct.pack('<%dq' % len(ids), *ids)))
            entries.append((name + '.rows', 'F32', [len(ids), width], rows))
        else:
            entries.append((name, info['dtype'], info['shape'], raw))
    out_header, offset = {}, 0
    meta = dict(meta)
    meta['derived_by'] = 'scripts/derive_clip_test_weights.py (token_embedding rows used by tokens.npy only)'
    out_header['__metadata__'] = meta
    for name, dtype, shape, raw in entries:
        out_header[name] = {'dtype': dtype, 'shape': shape, 'data_offsets': [offset, offset + len(raw)]}
        offset += len(raw)
    hj = json.dumps(out_header, separators=(',', ':')).encode()
    hj += b' ' * (-len(hj) % 8)
    with open(dst + '/weights_rows.safetensors', 'wb') as f:
        f.write(struct.pack('<Q', len(hj)) + hj)
        for _, _, _, raw in entries:
            f.write(raw)

if __name__ == '__main__':
    main(sys.argv[1], sys.argv[2])
