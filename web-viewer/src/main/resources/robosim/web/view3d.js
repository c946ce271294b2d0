// The 3D view (three.js, served from the jar): the arena as a floor, obstacles as extruded polygons,
// robots as cylinders of their radius with a nose for their heading. Metres; z up. Drag orbits, wheel zooms.
import * as THREE from '/three/three.module.min.js';

const WALL_M = 0.4, ROBOT_M = 0.3;

export class View3D {
  constructor(element) {
    this.element = element;
    this.renderer = null; // (made when first shown: a hidden page needs no WebGL)
    this.robots = [];
    this.yaw = -Math.PI / 2; this.pitch = 0.9; this.distance = 10; this.center = new THREE.Vector3();
  }

  // a world to show; keepCamera: it is the same arena (robots joined, a replay's seek): the camera stays
  world(w, keepCamera) {
    this.w = w;
    this.scene = new THREE.Scene();
    this.scene.background = new THREE.Color(0xf4f6fa);
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x777777, 2.2));
    const sun = new THREE.DirectionalLight(0xffffff, 1.5); sun.position.set(3, -4, 10); this.scene.add(sun);
    const a = w.arena, wm = (a.maxX - a.minX) / 1000, hm = (a.maxY - a.minY) / 1000;
    const floor = new THREE.Mesh(new THREE.PlaneGeometry(wm, hm), new THREE.MeshLambertMaterial({ color: 0xdadada }));
    floor.position.set((a.minX + a.maxX) / 2000, (a.minY + a.maxY) / 2000, 0);
    this.scene.add(floor);
    const wall = new THREE.MeshLambertMaterial({ color: 0x8a8a8a });
    for (const o of w.obstacles) {
      const shape = new THREE.Shape();
      for (let k = 0; k < o.xy.length; k += 2) {
        (k === 0 ? shape.moveTo : shape.lineTo).call(shape, o.xy[k] / 1000, o.xy[k + 1] / 1000);
      }
      this.scene.add(new THREE.Mesh(new THREE.ExtrudeGeometry(shape, { depth: WALL_M, bevelEnabled: false }), wall));
    }
    this.robots = w.robots.map((r) => {
      const g = new THREE.Group();
      const rm = r.radius / 1000;
      const body = new THREE.Mesh(new THREE.CylinderGeometry(rm, rm, ROBOT_M, 24),
        new THREE.MeshLambertMaterial({ color: 0x2a62c9 }));
      body.rotation.x = Math.PI / 2; body.position.z = ROBOT_M / 2;
      const nose = new THREE.Mesh(new THREE.BoxGeometry(rm, rm / 4, rm / 4), new THREE.MeshLambertMaterial({ color: 0x111111 }));
      nose.position.set(rm / 2, 0, ROBOT_M + rm / 8);
      g.add(body, nose);
      this.scene.add(g);
      return { group: g, body };
    });
    if (!keepCamera) this.fit();
  }

  fit() {
    if (!this.w) return;
    const a = this.w.arena;
    this.center.set((a.minX + a.maxX) / 2000, (a.minY + a.maxY) / 2000, 0);
    this.distance = 1.2 * Math.max(a.maxX - a.minX, a.maxY - a.minY) / 1000;
  }

  start() {
    this.renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    this.element.appendChild(this.renderer.domElement);
    this.camera = new THREE.PerspectiveCamera(50, 1, 0.05, 1000);
    this.camera.up.set(0, 0, 1);
    const el = this.renderer.domElement;
    let drag = null;
    el.addEventListener('mousedown', (e) => { drag = [e.clientX, e.clientY]; });
    window.addEventListener('mouseup', () => { drag = null; });
    window.addEventListener('mousemove', (e) => {
      if (!drag) return;
      this.yaw -= (e.clientX - drag[0]) * 0.01;
      this.pitch = Math.min(1.5, Math.max(0.1, this.pitch + (e.clientY - drag[1]) * 0.01));
      drag = [e.clientX, e.clientY];
    });
    el.addEventListener('wheel', (e) => { e.preventDefault(); this.distance *= e.deltaY < 0 ? 1 / 1.15 : 1.15; },
      { passive: false });
  }

  render(poses, gone, follow) {
    if (!this.scene || !poses) return;
    if (!this.renderer) this.start();
    const w = this.element.clientWidth, h = this.element.clientHeight;
    if (this.renderer.domElement.width !== w || this.renderer.domElement.height !== h) {
      this.renderer.setSize(w, h, false); this.camera.aspect = w / Math.max(1, h); this.camera.updateProjectionMatrix();
      this.renderer.domElement.style.width = '100%'; this.renderer.domElement.style.height = '100%';
    }
    this.robots.forEach((r, i) => {
      r.group.position.set(poses.x[i] / 1000, poses.y[i] / 1000, 0);
      r.group.rotation.z = poses.heading[i] * Math.PI / 180;
      r.body.material.color.set(gone.has(this.w.robots[i].name) ? 0xcccccc : i === follow ? 0xe8a200 : 0x2a62c9);
    });
    const c = follow >= 0 ? new THREE.Vector3(poses.x[follow] / 1000, poses.y[follow] / 1000, 0) : this.center;
    this.camera.position.set(c.x + this.distance * Math.cos(this.pitch) * Math.cos(this.yaw),
      c.y + this.distance * Math.cos(this.pitch) * Math.sin(this.yaw), this.distance * Math.sin(this.pitch));
    this.camera.lookAt(c);
    this.renderer.render(this.scene, this.camera);
  }
}
