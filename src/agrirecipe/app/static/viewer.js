// The 3D view: a scene's plants instanced from its own plant meshes (assets/*.glb).
//
// Scene coordinates are metres, X east, Y north, Z up; three.js is Y up, so a
// scene point (x, y, z) is drawn at (x, z, -y) and a yaw about Z is a turn about
// three's Y by the same angle. Level of detail: the plants nearest the camera are
// drawn with their meshes up to a triangle budget; the others as simple shapes
// (small fields) or points (large ones) in the field's foliage colour. The budget follows the measured frame rate.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';

const SKY = 0xcfe0ef;
const GRASS = 0x9db27c;
const SOIL = 0x8a6d4f;
const START_BUDGET = 60000;   // triangles drawn with full meshes
const MIN_BUDGET = 30000;
const MAX_BUDGET = 3000000;
const SHAPES_UP_TO = 20000;    // fields with more plants draw their far plants as points

function fmt(n) { return n.toLocaleString('en-US'); }

export class Viewer {
  constructor(canvas, status) {
    this.canvas = canvas;
    this.status = status;
    this.renderer = new THREE.WebGLRenderer({ canvas, antialias: false, powerPreference: 'high-performance' });
    this.renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
    this.scene = new THREE.Scene();
    this.scene.background = new THREE.Color(SKY);
    this.camera = new THREE.PerspectiveCamera(50, 1, 0.1, 50000);
    this.scene.add(new THREE.HemisphereLight(0xf4f8ff, 0x5b4a36, 1.6));
    const sun = new THREE.DirectionalLight(0xffffff, 2.2);
    sun.position.set(-0.6, 1.0, 0.4);
    this.scene.add(sun);
    this.controls = new OrbitControls(this.camera, canvas);
    this.controls.enableDamping = true;
    this.controls.maxPolarAngle = Math.PI * 0.495;
    this.controls.addEventListener('change', () => this.scheduleLod());
    this.group = new THREE.Group();
    this.scene.add(this.group);
    this.loader = new GLTFLoader();
    this.budget = START_BUDGET;
    this.frameTimes = [];
    this.lastFrame = 0;
    this.loadToken = 0;
    this.walkState = null;
    this.fields = [];
    this.ready = false;
    this.info = { shown: 0, total: 0, sampled: false, near: 0 };
    new ResizeObserver(() => this.resize()).observe(canvas.parentElement);
    this.resize();
    this.renderer.setAnimationLoop((t) => this.tick(t));
  }

  resize() {
    const box = this.canvas.parentElement.getBoundingClientRect();
    const w = Math.max(1, Math.floor(box.width)), h = Math.max(1, Math.floor(box.height));
    this.renderer.setSize(w, h, false);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.redraw();
  }

  /** Draw on the next frame (the view only draws when something changed). */
  redraw() { this.dirty = true; }

  tick(time) {
    let moved = false;
    if (this.walkState) { this.stepWalk(time); moved = true; }
    else moved = this.controls.update();
    if (!(moved || this.dirty)) { this.lastFrame = 0; return; }
    this.dirty = false;
    if (this.lastFrame) {
      this.frameTimes.push(time - this.lastFrame);
      if (this.frameTimes.length > 120) this.frameTimes.shift();
    }
    this.lastFrame = time;
    this.renderer.render(this.scene, this.camera);
    this.adaptBudget(time);
  }

  /** Mean frames per second over the last frames drawn. */
  fps() {
    if (this.frameTimes.length < 2) return 0;
    const mean = this.frameTimes.reduce((a, b) => a + b, 0) / this.frameTimes.length;
    return 1000 / mean;
  }

  adaptBudget(time) {
    if (!this.ready || this.walkState || time - (this.lastAdapt || 0) < 2500 || this.frameTimes.length < 30) return;
    this.lastAdapt = time;
    const fps = this.fps();
    let next = this.budget;
    if (fps < 12) next = Math.max(MIN_BUDGET, this.budget * 0.6);
    else if (fps > 30 && this.info.near < this.info.shown) next = Math.min(MAX_BUDGET, this.budget * 1.5);
    if (Math.abs(next - this.budget) > 1) { this.budget = next; this.updateLod(); }
  }

  clear() {
    this.stopWalk();
    for (const child of [...this.group.children]) {
      this.group.remove(child);
      child.traverse((o) => {
        if (o.geometry) o.geometry.dispose();
        if (o.material) (Array.isArray(o.material) ? o.material : [o.material]).forEach((m) => m.dispose());
      });
    }
    this.fields = [];
    this.ready = false;
  }

  async load(sceneId, maxPlants) {
    const token = ++this.loadToken;
    this.ready = false;
    this.status.textContent = 'loading the plants…';
    const query = maxPlants ? `?max_plants=${maxPlants}` : '';
    const [view, buffer] = await Promise.all([
      fetch(`/api/scenes/${sceneId}/view${query}`).then((r) => r.json()),
      fetch(`/api/scenes/${sceneId}/plants.bin${query}`).then((r) => r.arrayBuffer()),
    ]);
    const meshes = await Promise.all(view.fields.map((f) => Promise.all(
      f.files.map((file) => this.loader.loadAsync(`/api/scenes/${sceneId}/files/${file}`).catch(() => null)))));
    if (token !== this.loadToken) return;
    this.clear();
    this.view = view;
    this.buildGround(view);
    const data = new Float32Array(buffer);
    let offset = 0;
    view.fields.forEach((field, index) => {
      this.fields.push(this.buildField(field, data.subarray(offset * 6, (offset + field.shown) * 6), meshes[index]));
      offset += field.shown;
    });
    this.info = { shown: view.shown_plants, total: view.total_plants, sampled: view.sampled, near: 0 };
    this.overview();
    this.sceneId = sceneId;
    this.ready = true;
    this.updateLod();
  }

  buildGround(view) {
    const [x0, y0, x1, y1] = view.bounds;
    const span = Math.max(x1 - x0, y1 - y0, 10);
    const grass = new THREE.Mesh(new THREE.PlaneGeometry(span * 4, span * 4),
      new THREE.MeshLambertMaterial({ color: GRASS }));
    grass.rotation.x = -Math.PI / 2;
    grass.position.set((x0 + x1) / 2, -0.05, -(y0 + y1) / 2);
    this.group.add(grass);
    for (const field of view.fields) {
      const shape = new THREE.Shape(field.corners.map(([x, y]) => new THREE.Vector2(x, y)));
      const soil = new THREE.Mesh(new THREE.ShapeGeometry(shape),
        new THREE.MeshLambertMaterial({ color: SOIL, polygonOffset: true, polygonOffsetFactor: 1 }));
      soil.rotation.x = -Math.PI / 2;
      soil.position.y = -0.01;
      this.group.add(soil);
    }
  }

  buildField(field, records, gltfs) {
    const n = field.shown;
    const [ax, ay, az] = field.scale; // scene x, y, z scale of the mesh
    const matrices = new Float32Array(n * 16);
    const positions = new Float32Array(n * 3);
    const variants = new Uint8Array(n);
    const m = new THREE.Matrix4(), q = new THREE.Quaternion(), p = new THREE.Vector3(), s = new THREE.Vector3();
    const up = new THREE.Vector3(0, 1, 0);
    for (let i = 0; i < n; i++) {
      const x = records[i * 6], y = records[i * 6 + 1], z = records[i * 6 + 2];
      const yaw = records[i * 6 + 3], k = records[i * 6 + 4];
      variants[i] = records[i * 6 + 5];
      positions[i * 3] = x;
      positions[i * 3 + 1] = z + field.height_m * k * 0.5;
      positions[i * 3 + 2] = -y;
      q.setFromAxisAngle(up, yaw);
      p.set(x, z, -y);
      s.set(ax * k, az * k, ay * k);
      m.compose(p, q, s).toArray(matrices, i * 16);
    }
    // Far plants: in small fields a low shape each (a crown for trees, a cone for crops),
    // in large ones a point each (one vertex a plant keeps software WebGL fast), all in
    // one merged buffer drawn through an index that leaves out the plants shown as meshes.
    const shapes = n <= SHAPES_UP_TO;
    const far = shapes ? this.shapes(field, records, n) : new THREE.BufferGeometry();
    if (!shapes) far.setAttribute('position', new THREE.BufferAttribute(positions, 3));
    const per = shapes ? far.userData.indices : 1;
    far.userData.source = shapes ? far.index.array.slice() : null;
    far.setIndex(new THREE.BufferAttribute(new Uint32Array(Math.max(1, n * per)), 1));
    far.setDrawRange(0, 0);
    const farMaterial = shapes
      ? new THREE.MeshLambertMaterial({ vertexColors: true })
      : new THREE.PointsMaterial({ color: field.foliage, size: Math.max(field.canopy_m * 0.8, 0.3) });
    const points = shapes ? new THREE.Mesh(far, farMaterial) : new THREE.Points(far, farMaterial);
    points.userData.per = per;
    points.frustumCulled = false;
    this.group.add(points);
    // Near plants: per variant, the glTF's parts (trunk, leaves, fruit...) merged for
    // the chosen plants into one mesh per part, rebuilt when the camera settles.
    const parts = [];
    const tris = [];
    gltfs.forEach((gltf) => {
      const own = [];
      let count = 0;
      if (gltf) {
        gltf.scene.updateMatrixWorld(true);
        gltf.scene.traverse((o) => {
          if (!o.isMesh) return;
          const geometry = o.geometry.index ? o.geometry : o.geometry.setIndex([...Array(o.geometry.attributes.position.count).keys()]);
          count += geometry.index.count / 3;
          const source = o.material;
          const material = new THREE.MeshLambertMaterial({ color: source.color, side: source.side });
          const mesh = new THREE.Mesh(new THREE.BufferGeometry(), material);
          mesh.frustumCulled = false;
          mesh.visible = false;
          this.group.add(mesh);
          own.push({ geometry, local: o.matrixWorld.clone(), mesh });
        });
      }
      parts.push(own);
      tris.push(count);
    });
    return { field, n, matrices, positions, variants, points, parts, tris };
  }

  /** One low shape per plant, merged: a crown on a trunk for trees, a cone for crops. */
  shapes(field, records, n) {
    const tree = ['tree', 'vine', 'bush'].includes(field.growth_form);
    const parts = tree
      ? [[new THREE.IcosahedronGeometry(0.5, 0), field.foliage, 0.62, 0.62, 1.0],
        [new THREE.CylinderGeometry(0.05, 0.07, 1, 4, 1, true), '#6b4f36', 0.28, 0.08, 0.56]]
      : [[new THREE.ConeGeometry(0.5, 1, 5, 1, true), field.foliage, 0.5, 1.0, 1.0]];
    const bases = parts.map(([geometry, colour, at, width, height]) => {
      const base = geometry.index ? geometry.toNonIndexed() : geometry;
      return { base, colour: new THREE.Color(colour), at, width, height };
    });
    const perVerts = bases.reduce((c, b) => c + b.base.attributes.position.count, 0);
    const pos = new Float32Array(n * perVerts * 3), nor = new Float32Array(n * perVerts * 3);
    const col = new Float32Array(n * perVerts * 3), idx = new Uint32Array(n * perVerts);
    const m = new THREE.Matrix4(), q = new THREE.Quaternion(), p = new THREE.Vector3(), s = new THREE.Vector3();
    const nm = new THREE.Matrix3(), v = new THREE.Vector3(), up = new THREE.Vector3(0, 1, 0);
    let o = 0;
    for (let i = 0; i < n; i++) {
      const x = records[i * 6], y = records[i * 6 + 1], z = records[i * 6 + 2], k = records[i * 6 + 4];
      const h = field.height_m * k, w = field.canopy_m * k;
      q.setFromAxisAngle(up, records[i * 6 + 3]);
      for (const b of bases) {
        p.set(x, z + h * b.at, -y);
        s.set(w * b.width, h * b.height, w * b.width);
        m.compose(p, q, s);
        nm.getNormalMatrix(m);
        const P = b.base.attributes.position, N = b.base.attributes.normal;
        for (let j = 0; j < P.count; j++, o++) {
          v.fromBufferAttribute(P, j).applyMatrix4(m);
          pos.set([v.x, v.y, v.z], o * 3);
          v.fromBufferAttribute(N, j).applyMatrix3(nm).normalize();
          nor.set([v.x, v.y, v.z], o * 3);
          col.set([b.colour.r, b.colour.g, b.colour.b], o * 3);
          idx[o] = o;
        }
      }
    }
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(pos, 3));
    geometry.setAttribute('normal', new THREE.BufferAttribute(nor, 3));
    geometry.setAttribute('color', new THREE.BufferAttribute(col, 3));
    geometry.setIndex(new THREE.BufferAttribute(idx, 1));
    geometry.userData.indices = perVerts;
    return geometry;
  }

  scheduleLod() {
    if (!this.ready || this.walkState) return;
    clearTimeout(this.lodTimer);
    this.lodTimer = setTimeout(() => this.updateLod(), 200);
  }

  /** Choose the plants drawn as meshes: nearest first, within the triangle budget. */
  updateLod() {
    if (!this.ready) return;
    const cam = this.camera.position;
    const total = this.fields.reduce((c, f) => c + f.n, 0);
    let allTris = 0;
    for (const f of this.fields) for (let i = 0; i < f.n; i++) allTris += f.tris[f.variants[i]];
    const near = new Uint8Array(total);
    let nearCount = 0;
    if (allTris <= this.budget) {
      near.fill(1);
      nearCount = total;
    } else {
      const dist = new Float32Array(total);
      const owner = new Uint32Array(total);
      const local = new Uint32Array(total);
      let g = 0;
      this.fields.forEach((f, fi) => {
        for (let i = 0; i < f.n; i++, g++) {
          const dx = f.positions[i * 3] - cam.x, dy = f.positions[i * 3 + 1] - cam.y, dz = f.positions[i * 3 + 2] - cam.z;
          dist[g] = dx * dx + dy * dy + dz * dz;
          owner[g] = fi;
          local[g] = i;
        }
      });
      const order = new Uint32Array(total);
      for (let i = 0; i < total; i++) order[i] = i;
      order.sort((a, b) => dist[a] - dist[b]);
      let budget = this.budget;
      for (const k of order) {
        const f = this.fields[owner[k]];
        const t = f.tris[f.variants[local[k]]];
        if (!t) continue;
        if (t > budget) break;
        budget -= t;
        near[k] = 1;
        nearCount++;
      }
    }
    let g = 0;
    for (const f of this.fields) {
      const geometry = f.points.geometry;
      const index = geometry.index.array, source = geometry.userData.source, per = f.points.userData.per;
      let farCount = 0;
      const chosen = f.parts.map(() => []);
      for (let i = 0; i < f.n; i++, g++) {
        if (near[g] && f.tris[f.variants[i]]) chosen[f.variants[i]].push(i);
        else if (source) { index.set(source.subarray(i * per, i * per + per), farCount); farCount += per; }
        else index[farCount++] = i;
      }
      geometry.index.needsUpdate = true;
      geometry.setDrawRange(0, farCount);
      f.parts.forEach((own, v) => own.forEach((part) => this.merge(part, f.matrices, chosen[v])));
    }
    this.info.near = nearCount;
    this.showStatus();
    this.redraw();
  }

  /** One part of a plant mesh, copied to every chosen plant's place, as one geometry. */
  merge(part, matrices, chosen) {
    const { geometry, local, mesh } = part;
    mesh.geometry.dispose();
    if (!chosen.length) {
      mesh.visible = false;
      mesh.geometry = new THREE.BufferGeometry();
      return;
    }
    const P = geometry.attributes.position.array, N = geometry.attributes.normal ? geometry.attributes.normal.array : null;
    const I = geometry.index.array;
    const verts = P.length / 3;
    const pos = new Float32Array(P.length * chosen.length);
    const nor = new Float32Array(P.length * chosen.length);
    const idx = new Uint32Array(I.length * chosen.length);
    const m = new THREE.Matrix4(), w = new THREE.Matrix4(), nm = new THREE.Matrix3();
    chosen.forEach((i, c) => {
      m.fromArray(matrices, i * 16);
      w.multiplyMatrices(m, local);
      nm.getNormalMatrix(w);
      const e = w.elements, ne = nm.elements;
      const o = c * P.length;
      for (let j = 0; j < P.length; j += 3) {
        const x = P[j], y = P[j + 1], z = P[j + 2];
        pos[o + j] = e[0] * x + e[4] * y + e[8] * z + e[12];
        pos[o + j + 1] = e[1] * x + e[5] * y + e[9] * z + e[13];
        pos[o + j + 2] = e[2] * x + e[6] * y + e[10] * z + e[14];
        if (N) {
          const a = N[j], b = N[j + 1], d = N[j + 2];
          let nx = ne[0] * a + ne[3] * b + ne[6] * d, ny = ne[1] * a + ne[4] * b + ne[7] * d, nz = ne[2] * a + ne[5] * b + ne[8] * d;
          const len = Math.hypot(nx, ny, nz) || 1;
          nor[o + j] = nx / len; nor[o + j + 1] = ny / len; nor[o + j + 2] = nz / len;
        }
      }
      const base = c * verts, io = c * I.length;
      for (let j = 0; j < I.length; j++) idx[io + j] = I[j] + base;
    });
    const merged = new THREE.BufferGeometry();
    merged.setAttribute('position', new THREE.BufferAttribute(pos, 3));
    merged.setAttribute('normal', new THREE.BufferAttribute(nor, 3));
    merged.setIndex(new THREE.BufferAttribute(idx, 1));
    if (!N) merged.computeVertexNormals();
    mesh.geometry = merged;
    mesh.visible = true;
  }

  showStatus() {
    const { shown, total, near } = this.info;
    const parts = [];
    parts.push(this.info.sampled ? `showing ${fmt(shown)} of ${fmt(total)} plants (a seeded sample)` : `${fmt(total)} plants`);
    if (near < shown) parts.push(`the ${fmt(near)} nearest as meshes, the rest as simple shapes`);
    this.status.textContent = parts.join(' · ');
  }

  overview() {
    const [x0, y0, x1, y1] = this.view.bounds;
    const cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
    const span = Math.max(x1 - x0, y1 - y0, 8);
    this.stopWalk();
    this.controls.target.set(cx, 0, -cy);
    this.camera.position.set(cx + span * 0.45, span * 0.55, -cy + span * 0.85);
    this.camera.near = Math.max(0.05, span / 5000);
    this.camera.far = span * 40;
    this.camera.updateProjectionMatrix();
    this.controls.update();
    this.scheduleLod();
  }

  walk(onEnd) {
    const w = this.view && this.view.walk;
    if (!w) return false;
    const [sx, sy] = w.start, [ex, ey] = w.end;
    const length = Math.hypot(ex - sx, ey - sy);
    this.walkState = {
      from: new THREE.Vector3(sx, w.eye_m, -sy), to: new THREE.Vector3(ex, w.eye_m, -ey),
      start: performance.now(), seconds: Math.min(30, Math.max(6, length / 2)), lastLod: 0, onEnd,
    };
    this.controls.enabled = false;
    this.updateLod();
    return true;
  }

  stepWalk(time) {
    const st = this.walkState;
    const t = Math.min(1, (time - st.start) / (st.seconds * 1000));
    const dir = new THREE.Vector3().subVectors(st.to, st.from).normalize();
    this.camera.position.lerpVectors(st.from, st.to, t);
    this.camera.lookAt(this.camera.position.clone().addScaledVector(dir, 10).setY(st.from.y * 0.8));
    if (time - st.lastLod > 700) { st.lastLod = time; this.updateLod(); }
    if (t >= 1) this.stopWalk();
  }

  stopWalk() {
    const st = this.walkState;
    if (!st) return;
    this.walkState = null;
    const dir = new THREE.Vector3();
    this.camera.getWorldDirection(dir);
    this.controls.target.copy(this.camera.position).addScaledVector(dir, 10);
    this.controls.enabled = true;
    if (st.onEnd) st.onEnd();
  }
}
