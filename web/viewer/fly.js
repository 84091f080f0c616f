// Fly mode: WASD to move, Q/E down/up, Shift faster, drag to look around (yaw about the scene's up).
import * as THREE from "three";

const LOOK_SPEED = 0.004; // radians per dragged pixel
const MOVES = {
  KeyW: [0, 0, -1], KeyS: [0, 0, 1], KeyA: [-1, 0, 0], KeyD: [1, 0, 0], KeyQ: [0, -1, 0], KeyE: [0, 1, 0],
};

export class FlyMode {
  constructor(camera, element, speed) {
    this.camera = camera;
    this.speed = speed; // scene units per second
    this.enabled = false;
    this.held = new Set();
    this.dragging = null;
    this.look = { dx: 0, dy: 0 };
    window.addEventListener("keydown", (e) => {
      if (this.enabled && MOVES[e.code] && !isTyping(e)) this.held.add(e.code);
      if (e.key === "Shift") this.held.add("Shift");
    });
    window.addEventListener("keyup", (e) => this.held.delete(e.key === "Shift" ? "Shift" : e.code));
    window.addEventListener("blur", () => this.held.clear());
    element.addEventListener("pointerdown", (e) => {
      if (this.enabled) this.dragging = { x: e.clientX, y: e.clientY };
    });
    window.addEventListener("pointermove", (e) => {
      if (!this.dragging) return;
      this.look.dx += e.clientX - this.dragging.x;
      this.look.dy += e.clientY - this.dragging.y;
      this.dragging = { x: e.clientX, y: e.clientY };
    });
    window.addEventListener("pointerup", () => (this.dragging = null));
  }

  // Moves the camera for the `dt` seconds since the last frame; true when it moved.
  update(dt) {
    if (!this.enabled) return false;
    const cam = this.camera;
    let moved = false;
    if (this.look.dx || this.look.dy) {
      const yaw = new THREE.Quaternion().setFromAxisAngle(cam.up, -this.look.dx * LOOK_SPEED);
      const pitch = new THREE.Quaternion().setFromAxisAngle(new THREE.Vector3(1, 0, 0), -this.look.dy * LOOK_SPEED);
      cam.quaternion.premultiply(yaw).multiply(pitch);
      this.look = { dx: 0, dy: 0 };
      moved = true;
    }
    const step = new THREE.Vector3();
    for (const code of this.held) if (MOVES[code]) step.add(new THREE.Vector3(...MOVES[code]));
    if (step.lengthSq() > 0) {
      const fast = this.held.has("Shift") ? 4 : 1;
      // Q/E move along the scene's up; the others along the camera's own axes.
      const vertical = step.y;
      step.y = 0;
      step.applyQuaternion(cam.quaternion).addScaledVector(cam.up, vertical);
      cam.position.addScaledVector(step.normalize(), this.speed * fast * dt);
      moved = true;
    }
    return moved;
  }
}

function isTyping(e) {
  return e.target instanceof HTMLInputElement || e.target instanceof HTMLSelectElement;
}
