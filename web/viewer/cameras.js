// The scene's views (COLMAP/OpenCV: x_cam = R x_world + t; x right, y down, z forward) as three.js
// camera poses, projections and clickable frusta.
import * as THREE from "three";

const FRUSTUM_COLOR = 0xffc04d;
const TEST_FRUSTUM_COLOR = 0x4dd2ff;

// Rows of R are the camera's axes in world coordinates.
const axis = (view, row) => new THREE.Vector3(view.R[3 * row], view.R[3 * row + 1], view.R[3 * row + 2]);

// World pose of a three.js camera (looking down -z, y up) that sees what the view sees:
// C2W * diag(1, -1, -1) with C2W = [R^T | center].
export function viewPose(view) {
  const rotation = new THREE.Matrix4().makeBasis(axis(view, 0), axis(view, 1).negate(), axis(view, 2).negate());
  return {
    position: new THREE.Vector3(...view.center),
    quaternion: new THREE.Quaternion().setFromRotationMatrix(rotation),
  };
}

// OpenGL projection reproducing the pinhole u = fx x/z + cx, v = fy y/z + cy over the image's
// [0, width] x [0, height] (pixel i covers [i, i + 1)).
export function viewProjection(view, near, far) {
  const { width: w, height: h, fx, fy, cx, cy } = view;
  return new THREE.Matrix4().set(
    (2 * fx) / w, 0, 1 - (2 * cx) / w, 0,
    0, (2 * fy) / h, (2 * cy) / h - 1, 0,
    0, 0, -(far + near) / (far - near), (-2 * far * near) / (far - near),
    0, 0, -1, 0,
  );
}

// The views' mean "up" (-y of the camera), for orbiting: the scene frame's own up axis is arbitrary.
export function sceneUp(views) {
  const up = new THREE.Vector3();
  for (const view of views) up.sub(axis(view, 1));
  return up.lengthSq() > 0 ? up.normalize() : new THREE.Vector3(0, 1, 0);
}

export function viewForward(view) {
  return axis(view, 2);
}

// One line pyramid per view (apex at the camera, base = the image rectangle at depth `size`);
// each LineSegments carries its view in userData for picking.
export function makeFrusta(views, size) {
  const group = new THREE.Group();
  for (const view of views) {
    const { position, quaternion } = viewPose(view);
    // Image corners at depth `size`, in three.js camera coordinates (y up, looking down -z).
    const corners = [[0, 0], [view.width, 0], [view.width, view.height], [0, view.height]].map(
      ([u, v]) => new THREE.Vector3(((u - view.cx) / view.fx) * size, -((v - view.cy) / view.fy) * size, -size),
    );
    const apex = new THREE.Vector3();
    const points = [];
    corners.forEach((corner, k) => points.push(apex, corner, corner, corners[(k + 1) % 4]));
    // A tick above the top edge tells up from down.
    const top = corners[0].clone().lerp(corners[1], 0.5);
    points.push(top, top.clone().add(new THREE.Vector3(0, 0.15 * size, 0)));
    const lines = new THREE.LineSegments(
      new THREE.BufferGeometry().setFromPoints(points),
      new THREE.LineBasicMaterial({ color: view.test ? TEST_FRUSTUM_COLOR : FRUSTUM_COLOR }),
    );
    lines.position.copy(position);
    lines.quaternion.copy(quaternion);
    lines.userData.view = view;
    group.add(lines);
  }
  return group;
}
