// The 3D view (three.js, served from the jar): the arena as its floor (colour, image, painted regions) with low
// walls round it, obstacles as extruded polygons, objects as boxes and cylinders of their size and colour where they
// stand, lights as glowing spheres at their height, robots as cylinders of their radius and height with a nose for
// their heading, their lit LEDs as small spheres where they sit, and their name above them, their trails on the
// floor, and over it what the world's loop functions drew (a line a trace, in its colour). Metres; z up. Drag orbits, wheel zooms. Names are text laid over the canvas (set as textContent), placed
// where each robot is drawn.
import * as THREE from '/three/three.module.min.js';
import { paintFloor, objectPose, objectGone } from './scenery.js';

const WALL_M = 0.4, BOUNDS_M = 0.05, TRAIL_Z = 0.01, TRACE_Z = 0.012, LABEL_ABOVE_M = 0.15, FLOOR_PX = 1024,
  LED_M = 0.008, TRACE_POINTS = 64;

export class View3D {
  // trailPoints: the most points a trail the page keeps has
  constructor(element, trailPoints) {
    this.element = element;
    this.trailPoints = trailPoints;
    this.renderer = null; // (made when first shown: a hidden page needs no WebGL)
    this.robots = [];
    this.labels = document.createElement('div');
    element.appendChild(this.labels);
    this.yaw = -Math.PI / 2; this.pitch = 0.9; this.distance = 10; this.center = new THREE.Vector3();
  }

  // a world to show; keepCamera: it is the same arena (robots joined, a replay's seek): the camera stays;
  // picture: the floor's image, decoded (or null)
  world(w, keepCamera, picture) {
    this.w = w;
    this.scene = new THREE.Scene();
    this.scene.background = new THREE.Color(0xf4f6fa);
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x777777, 2.2));
    const sun = new THREE.DirectionalLight(0xffffff, 1.5); sun.position.set(3, -4, 10); this.scene.add(sun);
    const a = w.arena, x0 = a.minX / 1000, y0 = a.minY / 1000, x1 = a.maxX / 1000, y1 = a.maxY / 1000;
    this.picture = picture; this.paintSeen = '';
    const floor = new THREE.Mesh(new THREE.PlaneGeometry(x1 - x0, y1 - y0),
      new THREE.MeshLambertMaterial({ map: this.floorTexture(w, picture) }));
    this.floor = floor;
    floor.position.set((x0 + x1) / 2, (y0 + y1) / 2, 0);
    this.scene.add(floor);
    const wall = new THREE.MeshLambertMaterial({ color: 0x8a8a8a });
    const block = (bx0, by0, bx1, by1) => { // (the arena's walls, just outside it, as the 2D view's outline)
      const m = new THREE.Mesh(new THREE.BoxGeometry(bx1 - bx0, by1 - by0, WALL_M), wall);
      m.position.set((bx0 + bx1) / 2, (by0 + by1) / 2, WALL_M / 2);
      this.scene.add(m);
    };
    block(x0 - BOUNDS_M, y0 - BOUNDS_M, x1 + BOUNDS_M, y0);
    block(x0 - BOUNDS_M, y1, x1 + BOUNDS_M, y1 + BOUNDS_M);
    block(x0 - BOUNDS_M, y0, x0, y1);
    block(x1, y0, x1 + BOUNDS_M, y1);
    for (const o of w.obstacles) {
      const shape = new THREE.Shape();
      for (let k = 0; k < o.xy.length; k += 2) {
        (k === 0 ? shape.moveTo : shape.lineTo).call(shape, o.xy[k] / 1000, o.xy[k + 1] / 1000);
      }
      this.scene.add(new THREE.Mesh(new THREE.ExtrudeGeometry(shape, { depth: WALL_M, bevelEnabled: false }), wall));
    }
    this.objects = w.objects.map((o) => {
      const hm = o.height / 1000;
      const geometry = o.shape === 'cylinder' ? new THREE.CylinderGeometry(o.width / 2000, o.width / 2000, hm, 24)
        : new THREE.BoxGeometry(o.width / 1000, o.depth / 1000, hm);
      const mesh = new THREE.Mesh(geometry, new THREE.MeshLambertMaterial({ color: o.colour }));
      if (o.shape === 'cylinder') mesh.rotation.x = Math.PI / 2;
      const g = new THREE.Group();
      mesh.position.z = hm / 2;
      g.add(mesh);
      this.scene.add(g);
      return g;
    });
    for (const l of w.lights) {
      const lit = l.on && l.intensity > 0;
      const bulb = new THREE.Mesh(new THREE.SphereGeometry(0.05, 16, 12), lit
        ? new THREE.MeshBasicMaterial({ color: l.colour }) : new THREE.MeshLambertMaterial({ color: 0x999999 }));
      bulb.position.set(l.x / 1000, l.y / 1000, l.height / 1000);
      const pole = new THREE.Mesh(new THREE.CylinderGeometry(0.005, 0.005, l.height / 1000, 6),
        new THREE.MeshLambertMaterial({ color: 0x666666 }));
      pole.rotation.x = Math.PI / 2; pole.position.set(l.x / 1000, l.y / 1000, l.height / 2000);
      this.scene.add(bulb, pole);
    }
    const trailLine = new THREE.LineBasicMaterial({ color: 0x285ac8, transparent: true, opacity: 0.35 }); // (the 2D view's)
    this.robots = w.robots.map((r) => {
      const g = new THREE.Group();
      const rm = r.radius / 1000, hm = r.height / 1000;
      const body = new THREE.Mesh(new THREE.CylinderGeometry(rm, rm, hm, 24),
        new THREE.MeshLambertMaterial({ color: 0x2a62c9 }));
      body.rotation.x = Math.PI / 2; body.position.z = hm / 2;
      const nose = new THREE.Mesh(new THREE.BoxGeometry(rm, rm / 4, rm / 4), new THREE.MeshLambertMaterial({ color: 0x111111 }));
      nose.position.set(rm / 2, 0, hm + rm / 8);
      g.add(body, nose);
      const leds = r.leds.map(([lx, ly, lz]) => {
        const led = new THREE.Mesh(new THREE.SphereGeometry(LED_M, 8, 6), new THREE.MeshBasicMaterial({ color: 0 }));
        led.position.set(lx / 1000, ly / 1000, lz / 1000 + LED_M);
        led.visible = false;
        g.add(led);
        return led;
      });
      this.scene.add(g);
      const points = new THREE.BufferGeometry();
      points.setAttribute('position', new THREE.BufferAttribute(new Float32Array(3 * this.trailPoints), 3));
      const trail = new THREE.Line(points, trailLine);
      trail.frustumCulled = false; // (its bounds change with every point)
      this.scene.add(trail);
      const label = document.createElement('span');
      label.className = 'label';
      return { group: g, body, trail, label, text: '', leds, heightM: hm };
    });
    this.labels.replaceChildren(...this.robots.map((r) => r.label));
    this.traceLines = []; this.drawingShown = null; // (the scene is new: the drawing's lines are made again)
    if (!keepCamera) this.fit();
  }

  // the loop functions' drawing (viewer.js's: [{colour, points: [x, y mm, ...]}], whose traces and points only grow
  // until a new drawing replaces it): a line a trace, its points added as they come, its buffer doubled when full
  traces(drawing) {
    if (drawing !== this.drawingShown) {
      for (const l of this.traceLines) { this.scene.remove(l); l.geometry.dispose(); l.material.dispose(); }
      this.traceLines = []; this.drawingShown = drawing;
    }
    drawing.forEach((t, i) => {
      const n = t.points.length / 2;
      let line = this.traceLines[i];
      if (!line || line.capacity < n) {
        const old = line, capacity = Math.max(TRACE_POINTS, 2 * n);
        const points = new THREE.BufferGeometry();
        points.setAttribute('position', new THREE.BufferAttribute(new Float32Array(3 * capacity), 3));
        line = new THREE.Line(points, old ? old.material : new THREE.LineBasicMaterial({ color: t.colour }));
        line.frustumCulled = false; // (its bounds change with every point)
        points.setDrawRange(0, 0); line.capacity = capacity; line.shown = 0;
        if (old) { this.scene.remove(old); old.geometry.dispose(); }
        this.scene.add(line);
        this.traceLines[i] = line;
      }
      if (line.shown < n) {
        const at = line.geometry.attributes.position;
        for (let k = line.shown; k < n; k++) at.setXYZ(k, t.points[2 * k] / 1000, t.points[2 * k + 1] / 1000, TRACE_Z);
        at.needsUpdate = true;
        line.geometry.setDrawRange(0, n);
        line.shown = n;
      }
    });
  }

  // the floor as a texture: painted as the 2D view paints it, FLOOR_PX on its longer side
  floorTexture(w, picture, paint) {
    const a = w.arena, scale = FLOOR_PX / Math.max(a.maxX - a.minX, a.maxY - a.minY);
    const c = document.createElement('canvas');
    c.width = Math.max(1, Math.round((a.maxX - a.minX) * scale)); c.height = Math.max(1, Math.round((a.maxY - a.minY) * scale));
    paintFloor(c.getContext('2d'), w.floor, a, picture, (x) => (x - a.minX) * scale, (y) => (a.maxY - y) * scale, scale,
      paint);
    const t = new THREE.CanvasTexture(c);
    t.colorSpace = THREE.SRGBColorSpace;
    return t;
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

  // poses: the update to show; gone, held: names of robots that left or are held (drawn grey, said so);
  // trails: each robot's trail (x, y mm pairs, oldest first), or null for none; drawing: the loop functions' (traces)
  render(poses, gone, held, follow, trails, drawing) {
    if (!this.scene || !poses) return;
    if (!this.renderer) this.start();
    const paint = JSON.stringify(poses.paint || []);
    if (paint !== this.paintSeen) { // (the loop functions painted anew: the floor's texture again)
      this.paintSeen = paint;
      this.floor.material.map.dispose();
      this.floor.material.map = this.floorTexture(this.w, this.picture, poses.paint);
      this.floor.material.needsUpdate = true;
    }
    const w = this.element.clientWidth, h = this.element.clientHeight;
    if (this.renderer.domElement.width !== w || this.renderer.domElement.height !== h) {
      this.renderer.setSize(w, h, false); this.camera.aspect = w / Math.max(1, h); this.camera.updateProjectionMatrix();
      this.renderer.domElement.style.width = '100%'; this.renderer.domElement.style.height = '100%';
    }
    this.robots.forEach((r, i) => {
      const name = this.w.robots[i].name, out = gone.has(name) || held.has(name);
      r.group.position.set(poses.x[i] / 1000, poses.y[i] / 1000, 0);
      r.group.rotation.z = poses.heading[i] * Math.PI / 180;
      r.body.material.color.set(out ? 0xcccccc : i === follow ? 0xe8a200 : 0x2a62c9);
      const lit = poses.leds ? poses.leds[i] || [] : [];
      r.leds.forEach((led, k) => {
        led.visible = !!lit[k] && lit[k] !== '#000000';
        if (led.visible) led.material.color.set(lit[k]);
      });
      this.trail(r.trail, trails && trails[i]);
    });
    this.objects.forEach((g, i) => {
      g.visible = !objectGone(poses, i); // (the loop functions took it out of the world)
      const [x, y, h] = objectPose(this.w, poses, i);
      g.position.set(x / 1000, y / 1000, 0);
      g.rotation.z = h * Math.PI / 180;
    });
    this.traces(drawing);
    const c = follow >= 0 ? new THREE.Vector3(poses.x[follow] / 1000, poses.y[follow] / 1000, 0) : this.center;
    this.camera.position.set(c.x + this.distance * Math.cos(this.pitch) * Math.cos(this.yaw),
      c.y + this.distance * Math.cos(this.pitch) * Math.sin(this.yaw), this.distance * Math.sin(this.pitch));
    this.camera.lookAt(c);
    this.renderer.render(this.scene, this.camera);
    this.robots.forEach((r, i) => {
      const name = this.w.robots[i].name;
      this.label(r, name + (held.has(name) ? ' (held)' : gone.has(name) ? ' (left)' : ''),
        new THREE.Vector3(poses.x[i] / 1000, poses.y[i] / 1000, r.heightM + LABEL_ABOVE_M).project(this.camera), w, h);
    });
  }

  // a robot's trail line: the points of t (x, y mm pairs), or none
  trail(line, t) {
    const n = t ? Math.min(t.length / 2, this.trailPoints) : 0, at = line.geometry.attributes.position;
    for (let k = 0; k < n; k++) at.setXYZ(k, t[2 * k] / 1000, t[2 * k + 1] / 1000, TRAIL_Z);
    at.needsUpdate = n > 0;
    line.geometry.setDrawRange(0, n);
  }

  // a robot's name over the canvas where p (projected, -1 to 1 across the view) is; hidden behind the camera
  label(r, text, p, w, h) {
    if (r.text !== text) { r.label.textContent = text; r.text = text; }
    r.label.hidden = p.z > 1;
    r.label.style.transform = `translate(${((p.x + 1) / 2 * w).toFixed(1)}px, ${((1 - p.y) / 2 * h).toFixed(1)}px) translate(-50%, -100%)`;
  }
}
