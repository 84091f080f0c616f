// CityLangSplat viewer: the trained Gaussians (Spark), the scene's cameras, open-vocabulary queries
// recolouring the splats, and the answer as ranked city objects.
import * as THREE from "three";
import { OrbitControls } from "three/addons/controls/OrbitControls.js";
import { SparkRenderer } from "@sparkjsdev/spark";
import * as api from "./api.js";
import { makeFrusta, sceneUp, viewForward, viewPose, viewProjection } from "./cameras.js";
import { heatGradient } from "./colormap.js";
import { FlyMode } from "./fly.js";
import { Splats } from "./splats.js";

const $ = (id) => document.getElementById(id);
const CLICK_SLOP = 5; // pixels a press may move and still count as a click
const FREE_FOV = 50;
const THRESHOLD_RANGE = { cosine: [-1, 1], relevancy: [0, 1] };
// Splats whose centres lie farther outside the scene's box than this share of its diagonal are
// hidden by default: the sky and background that train-rgb grows far away would fog every view.
const FAR_MARGIN = 0.5;

// Test hooks (tests/viewer/browser_query_check.py). `frames` counts animation frames that show
// everything up to date: the page redraws only on change, and a frame while Spark still sorts
// the splats for a new camera does not count. `firstView`: the view the page opened at; `hidden`:
// how many splats "hide far splats" hides.
const state = { ready: false, frames: 0, query: null, view: null, firstView: null, hidden: 0 };
window.viewerState = state;

const stage = $("stage");
const renderer = new THREE.WebGLRenderer({ antialias: false }); // Spark: MSAA only costs
stage.append(renderer.domElement);
const scene = new THREE.Scene();
scene.background = new THREE.Color(0x202226);
const camera = new THREE.PerspectiveCamera(FREE_FOV, 1, 0.01, 1000);
const spark = new SparkRenderer({ renderer });
scene.add(spark);
let controls = null; // made once the scene's up axis is known: OrbitControls fixes it at construction
let fly = null;
// Read-only test hook: the camera the page draws with (world position, quaternion x y z w, projection
// column-major) and the canvas size, to compare with a view's pose and intrinsics.
window.viewerCamera = () => ({
  position: camera.position.toArray(),
  quaternion: camera.quaternion.toArray(),
  projection: camera.projectionMatrix.toArray(),
  canvas: [renderer.domElement.width, renderer.domElement.height],
  view: activeView?.name ?? null,
});

let model = null;
let splats = null;
let frusta = null;
let cityMesh = null;
let cityMeshData = null; // promise of /api/citymesh: its bounds are part of the scene's box
let proposals = null; // THREE.Group of `changes`' proposed openings, made at the first toggle
let sceneBox = null; // THREE.Box3: the camera centres and the city model (sceneBoxOf)
let activeView = null; // the view whose pose and intrinsics the camera has, or null (free camera)
let current = null; // the applied query: {params, answer, scores}
let querySeq = 0;
let flight = null; // camera animation towards an object
let needsRender = true;

// Drawing on demand keeps an idle page (and a software-rendered test browser) cheap.
function invalidate() {
  needsRender = true;
}

function showError(error) {
  $("error").textContent = error ? String(error.message ?? error) : "";
  $("error").hidden = !error;
  if (error) console.warn(error);
}

function setStatus(text) {
  $("status").textContent = text;
}

// ---- layout: the render area is the whole stage, or the view's aspect ratio letterboxed in it.

function layout() {
  const { clientWidth: w, clientHeight: h } = stage;
  if (!w || !h) return;
  let width = w;
  let height = h;
  if (activeView) {
    const aspect = activeView.width / activeView.height;
    if (w / h > aspect) width = Math.round(h * aspect);
    else height = Math.round(w / aspect);
  }
  renderer.setSize(width, height);
  updateProjection();
  invalidate();
}

function updateProjection() {
  if (activeView) {
    camera.projectionMatrix.copy(viewProjection(activeView, camera.near, camera.far));
    camera.projectionMatrixInverse.copy(camera.projectionMatrix).invert();
  } else {
    const size = renderer.getSize(new THREE.Vector2());
    camera.aspect = size.x / size.y;
    camera.updateProjectionMatrix();
  }
}

// ---- views

function enterView(view) {
  flight = null;
  activeView = view;
  // Its own frustum would only outline the image border.
  for (const lines of frusta.children) lines.visible = lines.userData.view !== view;
  state.view = view.name;
  $("view-select").value = view.name;
  const { position, quaternion } = viewPose(view);
  camera.position.copy(position);
  camera.quaternion.copy(quaternion);
  // Orbit about the point the view looks at, as far away as the scene's centre.
  const forward = viewForward(view);
  const depth = Math.max(sceneCenter().sub(position).dot(forward), sceneRadius() * 0.1);
  controls.target.copy(position).addScaledVector(forward, depth);
  showPhoto(view);
  layout();
}

// Back to free navigation, keeping the pose; the field of view continues the view's.
function leaveView() {
  if (!activeView) return;
  camera.fov = THREE.MathUtils.radToDeg(2 * Math.atan(activeView.height / (2 * activeView.fy)));
  activeView = null;
  state.view = null;
  for (const lines of frusta.children) lines.visible = true;
  $("view-select").value = "";
  layout();
}

function showPhoto(view) {
  $("view-photo").src = view.image;
  $("photo-name").textContent = view.name + (view.test ? " (test)" : "");
}

// ---- scene framing

function sceneCenter() {
  const { min, max } = model.bounds;
  return new THREE.Vector3(...min).add(new THREE.Vector3(...max)).multiplyScalar(0.5);
}

function sceneRadius() {
  const { min, max } = model.bounds;
  return Math.max(new THREE.Vector3(...max).distanceTo(new THREE.Vector3(...min)) / 2, 1e-3);
}

function frameBounds(center = sceneCenter(), radius = sceneRadius()) {
  // Look the way the photos were taken, from far enough to see the whole bounding sphere.
  const forward = new THREE.Vector3();
  for (const view of model.views) forward.add(viewForward(view));
  if (forward.lengthSq() === 0) forward.set(-1, -1, -1);
  forward.normalize();
  const distance = (1.1 * radius) / Math.sin(THREE.MathUtils.degToRad(FREE_FOV / 2));
  camera.position.copy(center).addScaledVector(forward, -distance);
  controls.target.copy(center);
  camera.lookAt(center);
}

// The first view train-rgb trains on (views by name, every 8th held out: the server marks those
// `test`); a scene of held-out views only opens at its first one.
function firstTrainingView(views) {
  const byName = [...views].sort((a, b) => (a.name < b.name ? -1 : a.name > b.name ? 1 : 0));
  return byName.find((v) => !v.test) ?? byName[0] ?? null;
}

// Opens where a person sees the building: through the first training camera, else the whole city
// model, else the bounding sphere of the bulk of the Gaussians.
function frameFirst(cityBox) {
  const view = firstTrainingView(model.views);
  if (view) {
    enterView(view);
  } else if (cityBox) {
    const sphere = cityBox.getBoundingSphere(new THREE.Sphere());
    frameBounds(sphere.center, Math.max(sphere.radius, 1e-3));
  } else {
    frameBounds();
  }
  state.firstView = view?.name ?? null;
}

// Smoothly moves the camera to look at a sphere (an object of the answer).
function flyTo(center, radius) {
  leaveView();
  const forward = controls.target.clone().sub(camera.position).normalize();
  const distance = (1.5 * radius) / Math.sin(THREE.MathUtils.degToRad(camera.fov / 2));
  flight = {
    from: { position: camera.position.clone(), target: controls.target.clone() },
    to: { position: center.clone().addScaledVector(forward, -distance), target: center.clone() },
    start: performance.now(),
    duration: 600,
  };
}

function stepFlight(now) {
  const t = Math.min(1, (now - flight.start) / flight.duration);
  const ease = t * t * (3 - 2 * t);
  camera.position.lerpVectors(flight.from.position, flight.to.position, ease);
  controls.target.lerpVectors(flight.from.target, flight.to.target, ease);
  camera.lookAt(controls.target);
  if (t === 1) flight = null;
}

// ---- queries

function thresholdValue() {
  return Number($("threshold").value);
}

async function runQuery() {
  const text = $("query").value.trim();
  if (!text || !splats) return;
  const params = { text, level: $("level").value, mode: $("mode").value, threshold: thresholdValue() };
  const seq = ++querySeq;
  state.query = { text, level: null, applied: false, selected: 0 };
  showError(null);
  setStatus(`querying “${text}”…`);
  const started = performance.now();
  try {
    const { answer, scores } = await api.runQuery(params, splats.count);
    if (seq !== querySeq) return; // superseded by a newer query
    current = { params, answer, scores };
    applyScores();
    renderObjects(answer);
    setStatus(`“${text}”: ${Math.round(performance.now() - started)} ms`);
  } catch (error) {
    if (seq !== querySeq) return;
    state.query.error = error.message;
    setStatus("query failed");
    showError(error);
  }
}

// Recolours from the current scores at the slider's threshold (no refetch).
function applyScores() {
  const threshold = thresholdValue();
  const { selected, max } = splats.highlight(current.scores, threshold);
  invalidate();
  const { answer, params } = current;
  state.query = { text: params.text, level: answer.level, applied: true, selected };
  $("query-summary").textContent =
    `level ${answer.level} · ${selected.toLocaleString()} of ${splats.count.toLocaleString()} Gaussians ≥ ${threshold.toFixed(2)}`;
  $("legend").hidden = false;
  $("legend-lo").textContent = threshold.toFixed(2);
  $("legend-hi").textContent = max.toFixed(2);
}

function clearQuery() {
  querySeq++;
  current = null;
  state.query = null;
  splats?.clear();
  invalidate();
  $("objects").tBodies[0].replaceChildren();
  $("query-summary").textContent = "";
  $("legend").hidden = true;
  showError(null);
}

function renderObjects(answer) {
  const body = $("objects").tBodies[0];
  body.replaceChildren();
  if (!model.has_objects) {
    const row = body.insertRow();
    row.insertCell().textContent = "no city objects in this model";
    row.cells[0].colSpan = 6;
    return;
  }
  for (const object of answer.objects ?? []) {
    const row = body.insertRow();
    // A BuildingPart's objects are listed with their building, the part beside it.
    const building = object.part ? `${object.building} / ${object.part}` : object.building;
    const cells = [object.rank, object.class, object.id, building, object.gaussians.toLocaleString(),
      object.mean_score.toFixed(3)];
    for (const value of cells) row.insertCell().textContent = value;
    row.title = `${object.class} ${object.id} of building ${building}: max ${object.max_score.toFixed(3)}, ` +
      `${(100 * object.above).toFixed(0)}% above the threshold — click to fly there`;
    row.addEventListener("click", () => flyTo(new THREE.Vector3(...object.center), object.radius));
  }
}

function setThresholdRange(mode) {
  const slider = $("threshold");
  [slider.min, slider.max] = THRESHOLD_RANGE[mode];
  $("threshold-value").textContent = thresholdValue().toFixed(2);
}

// ---- city model overlay

// Fetched once, at load (its bounds) or by the toggle.
function loadCityMesh() {
  cityMeshData ??= api.getCityMesh();
  return cityMeshData;
}

function boxOfVertices(data) {
  const box = new THREE.Box3();
  const point = new THREE.Vector3();
  for (let o = 0; o + 2 < data.length; o += 6) box.expandByPoint(point.set(data[o], data[o + 1], data[o + 2]));
  return box.isEmpty() ? null : box;
}

async function toggleCityMesh() {
  const button = $("citymesh-toggle");
  const show = button.getAttribute("aria-pressed") !== "true";
  button.setAttribute("aria-pressed", String(show));
  if (show && !cityMesh) {
    try {
      const data = await loadCityMesh();
      const buffer = new THREE.InterleavedBuffer(data, 6);
      const geometry = new THREE.BufferGeometry();
      geometry.setAttribute("position", new THREE.InterleavedBufferAttribute(buffer, 3, 0));
      geometry.setAttribute("color", new THREE.InterleavedBufferAttribute(buffer, 3, 3));
      cityMesh = new THREE.Mesh(geometry, new THREE.MeshBasicMaterial({
        vertexColors: true, transparent: true, opacity: 0.4, side: THREE.DoubleSide, depthWrite: false,
      }));
      cityMesh.renderOrder = 1; // after the splats, so it lies over them
      scene.add(cityMesh);
    } catch (error) {
      cityMeshData = null; // a later click asks again
      button.setAttribute("aria-pressed", "false");
      showError(error);
      return;
    }
  }
  if (cityMesh) cityMesh.visible = show;
  invalidate();
}

// ---- `changes`' proposals: each a rectangle, outlined, filled more opaquely the higher its confidence

async function toggleChanges() {
  const button = $("changes-toggle");
  const show = button.getAttribute("aria-pressed") !== "true";
  button.setAttribute("aria-pressed", String(show));
  if (show && !proposals) {
    try {
      const changes = await api.getChanges();
      proposals = new THREE.Group();
      for (const p of changes.proposals) {
        const corners = p.corners.map((c) => new THREE.Vector3(...c));
        const outline = new THREE.LineLoop(new THREE.BufferGeometry().setFromPoints(corners),
          new THREE.LineBasicMaterial({ color: 0xff4020, depthTest: false }));
        const fill = new THREE.Mesh(
          new THREE.BufferGeometry().setFromPoints([corners[0], corners[1], corners[2], corners[0], corners[2], corners[3]]),
          new THREE.MeshBasicMaterial({ color: 0xff4020, transparent: true, opacity: 0.1 + 0.5 * p.confidence,
                                        side: THREE.DoubleSide, depthWrite: false }));
        outline.renderOrder = fill.renderOrder = 2;
        proposals.add(outline, fill);
        const item = document.createElement("li");
        item.textContent = `${p.id}: ${p.class}, ${p.width.toFixed(2)} x ${p.height.toFixed(2)} m, confidence ${p.confidence.toFixed(2)}`;
        $("changes-list").append(item);
      }
      scene.add(proposals);
    } catch (error) {
      button.setAttribute("aria-pressed", "false");
      showError(error);
      return;
    }
  }
  if (proposals) proposals.visible = show;
  $("changes-list").hidden = !show;
  invalidate();
}

// ---- far splats

// The scene's box: the camera centres and the city model where the page has them (the photos were
// taken around what matters); else, or when they span no volume (one camera), also the server's
// 1st-99th percentile box of the Gaussians' centres.
function sceneBoxOf(views, cityBox) {
  const box = new THREE.Box3();
  for (const view of views) box.expandByPoint(new THREE.Vector3(...view.center));
  if (cityBox) box.union(cityBox);
  const size = box.getSize(new THREE.Vector3());
  if (box.isEmpty() || Math.min(size.x, size.y, size.z) <= 0) {
    box.union(new THREE.Box3(new THREE.Vector3(...model.bounds.min), new THREE.Vector3(...model.bounds.max)));
  }
  return box;
}

// Hides the splats whose centres lie outside the scene's box grown by FAR_MARGIN of its diagonal,
// or shows all; a query's colours stay.
function applyFarSplats() {
  const hide = $("farsplats-toggle").getAttribute("aria-pressed") === "true";
  const keep = hide ? sceneBox.clone().expandByScalar(FAR_MARGIN * sceneBox.min.distanceTo(sceneBox.max)) : null;
  state.hidden = splats.hideOutside(keep);
  $("farsplats-toggle").title = hide
    ? `${state.hidden.toLocaleString()} of ${splats.count.toLocaleString()} splats lie far outside the scene ` +
      "(its cameras and city model) and are hidden — click to show them"
    : "Hide the splats far outside the scene (its cameras and city model), e.g. the sky";
  if (current) applyScores();
  else splats.clear();
  invalidate();
}

// ---- input

function setFly(on) {
  fly.enabled = on;
  controls.enabled = !on;
  $("fly-toggle").setAttribute("aria-pressed", String(on));
  if (!on) {
    // Orbit on from where the flight left off, about a point straight ahead.
    const distance = camera.position.distanceTo(controls.target);
    controls.target.copy(camera.position).addScaledVector(camera.getWorldDirection(new THREE.Vector3()), distance);
  }
}

function pickFrustum(event) {
  const rect = renderer.domElement.getBoundingClientRect();
  const ndc = new THREE.Vector2(((event.clientX - rect.left) / rect.width) * 2 - 1,
    -((event.clientY - rect.top) / rect.height) * 2 + 1);
  const raycaster = new THREE.Raycaster();
  raycaster.params.Line.threshold = sceneRadius() * 0.01;
  raycaster.setFromCamera(ndc, camera);
  const hit = raycaster.intersectObject(frusta, true)[0];
  if (hit) enterView(hit.object.userData.view);
}

function wireUi() {
  $("query-form").addEventListener("submit", (e) => {
    e.preventDefault();
    runQuery();
  });
  $("threshold").addEventListener("input", () => {
    $("threshold-value").textContent = thresholdValue().toFixed(2);
    if (current) applyScores();
  });
  $("mode").addEventListener("change", () => {
    setThresholdRange($("mode").value);
    if (current) runQuery();
  });
  $("level").addEventListener("change", () => current && runQuery());
  $("clear").addEventListener("click", clearQuery);
  $("view-select").addEventListener("change", (e) => {
    const view = model.views.find((v) => v.name === e.target.value);
    if (view) enterView(view);
    else leaveView();
  });
  $("fly-toggle").addEventListener("click", () => setFly(!fly.enabled));
  $("citymesh-toggle").addEventListener("click", toggleCityMesh);
  $("changes-toggle").addEventListener("click", toggleChanges);
  $("farsplats-toggle").addEventListener("click", (e) => {
    e.target.setAttribute("aria-pressed", String(e.target.getAttribute("aria-pressed") !== "true"));
    if (splats) applyFarSplats();
  });
  $("photo-toggle").addEventListener("click", (e) => {
    const show = e.target.getAttribute("aria-pressed") !== "true";
    e.target.setAttribute("aria-pressed", String(show));
    $("photo-panel").hidden = !show;
  });
  window.addEventListener("keydown", (e) => {
    if (e.code === "KeyF" && !(e.target instanceof HTMLInputElement || e.target instanceof HTMLSelectElement)) {
      setFly(!fly.enabled);
    }
  });
  // Any orbit movement (drag, wheel) leaves the view's exact pose for free navigation.
  controls.addEventListener("change", () => {
    leaveView();
    invalidate();
  });
  let press = null;
  renderer.domElement.addEventListener("pointerdown", (e) => (press = { x: e.clientX, y: e.clientY }));
  renderer.domElement.addEventListener("pointerup", (e) => {
    if (press && Math.hypot(e.clientX - press.x, e.clientY - press.y) < CLICK_SLOP) pickFrustum(e);
    press = null;
  });
  new ResizeObserver(layout).observe(stage);
}

function fillControls() {
  for (const level of model.levels) $("level").add(new Option(`level ${level}`, String(level)));
  for (const view of model.views) {
    $("view-select").add(new Option(view.name + (view.test ? " (test)" : ""), view.name));
  }
  setThresholdRange($("mode").value);
  $("legend-ramp").style.background = heatGradient();
  if (model.warning) {
    $("warning").textContent = model.warning;
    $("warning").hidden = false;
  }
  $("changes-toggle").textContent = `proposals (${model.changes ?? 0})`;
  if (!model.changes) {
    $("changes-toggle").disabled = true;
    $("changes-toggle").title = "no `changes` output beside this run (citylangsplat changes RUN)";
  }
  if (!model.city_mesh) {
    $("citymesh-toggle").disabled = true;
    $("citymesh-toggle").title = "this model has no city model";
  }
}

// ---- render loop

let lastTime = performance.now();
function frame(now) {
  const dt = Math.min(0.1, (now - lastTime) / 1000);
  lastTime = now;
  if (flight) {
    stepFlight(now);
    invalidate();
  }
  if (fly.update(dt)) {
    leaveView();
    invalidate();
  }
  if (needsRender || spark.dirty) {
    needsRender = false;
    renderer.render(scene, camera);
  }
  if (!spark.sorting && !spark.sortDirty) state.frames++;
  // Ready once Spark has sorted and drawn the splats, not merely once they were handed over.
  if (!state.ready && splats && spark.activeSplats > 0) {
    state.ready = true;
  }
}

async function main() {
  const started = performance.now();
  model = await api.getModel();
  fillControls();
  // The city model's bounds frame a scene without views and bound the far splats; without them
  // the page still works.
  let cityBox = null;
  if (model.city_mesh) {
    try {
      cityBox = boxOfVertices(await loadCityMesh());
    } catch (error) {
      cityMeshData = null;
      console.warn(error);
    }
  }
  sceneBox = sceneBoxOf(model.views, cityBox);
  const radius = sceneRadius();
  camera.near = radius * 1e-3;
  camera.far = radius * 1e3;
  camera.up.copy(sceneUp(model.views));
  controls = new OrbitControls(camera, renderer.domElement);
  fly = new FlyMode(camera, renderer.domElement, radius * 0.5);
  frusta = makeFrusta(model.views, radius * 0.08);
  scene.add(frusta);
  frameFirst(cityBox);
  wireUi();
  layout();
  renderer.setAnimationLoop(frame);
  setStatus(`loading ${model.gaussians.toLocaleString()} Gaussians…`);
  splats = new Splats(await api.getGaussians(model.gaussians));
  applyFarSplats();
  scene.add(splats.mesh);
  invalidate();
  const seconds = ((performance.now() - started) / 1000).toFixed(1);
  const hidden = state.hidden ? ` (${state.hidden.toLocaleString()} far ones hidden)` : "";
  setStatus(`${model.gaussians.toLocaleString()} Gaussians${hidden} · ${model.method} · ${model.provider} features · ${seconds} s`);
}

main().catch((error) => {
  setStatus("failed to load");
  showError(error);
});
