// The viewer's HTTP API (served by `citylangsplat view`, same origin).

async function fetchOk(url) {
  const response = await fetch(url);
  if (!response.ok) {
    // The server answers errors as {"error": "..."}; anything else still gets a readable message.
    let message = `${response.status} ${response.statusText}`;
    try {
      message = (await response.json()).error ?? message;
    } catch {}
    throw new Error(`${url.split("?")[0]}: ${message}`);
  }
  return response;
}

export async function getModel() {
  return (await fetchOk("/api/model")).json();
}

// N records of 14 float32: x y z, sx sy sz, qw qx qy qz, opacity, r g b.
export async function getGaussians(count) {
  const data = new Float32Array(await (await fetchOk("/api/gaussians")).arrayBuffer());
  if (data.length !== count * 14) {
    throw new Error(`/api/gaussians: ${data.length / 14} records, /api/model says ${count}`);
  }
  return data;
}

// Non-indexed triangles, per vertex x y z r g b.
export async function getCityMesh() {
  return new Float32Array(await (await fetchOk("/api/citymesh")).arrayBuffer());
}

// `changes`' proposed openings in the scene frame: {proposals: [{id, class, confidence, width, height, corners}]}.
export async function getChanges() {
  return (await fetchOk("/api/changes")).json();
}

// The query's answer (JSON) and its per-Gaussian scores, fetched together.
export async function runQuery({ text, level, mode, threshold }, count) {
  const params = new URLSearchParams({ q: text, level, mode });
  const [answer, buffer] = await Promise.all([
    fetchOk(`/api/query?${params}&threshold=${threshold}`).then((r) => r.json()),
    fetchOk(`/api/scores?${params}`).then((r) => r.arrayBuffer()),
  ]);
  const scores = new Float32Array(buffer);
  if (scores.length !== count) {
    throw new Error(`/api/scores: ${scores.length} scores for ${count} Gaussians`);
  }
  return { answer, scores };
}
