// SPDX-License-Identifier: MIT
// The 3D replay (three.js): the barrier's posts tilting and failing, the cables as polylines coloured by
// the tension of each span, the vehicle as a box with its front face, moving and pitching. World frame
// of the simulator: x along the barrier, y toward the protected side, z up.
import {
  AmbientLight,
  BoxGeometry,
  BufferGeometry,
  CanvasTexture,
  Color,
  CylinderGeometry,
  DirectionalLight,
  EdgesGeometry,
  Fog,
  GridHelper,
  Group,
  HemisphereLight,
  Line,
  LineBasicMaterial,
  LineDashedMaterial,
  LineSegments,
  Mesh,
  MeshBasicMaterial,
  MeshLambertMaterial,
  PerspectiveCamera,
  PlaneGeometry,
  Quaternion,
  Scene,
  SRGBColorSpace,
  Vector3,
  WebGLRenderer,
} from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { LineSegments2 } from 'three/addons/lines/LineSegments2.js';
import { LineSegmentsGeometry } from 'three/addons/lines/LineSegmentsGeometry.js';
import { LineMaterial } from 'three/addons/lines/LineMaterial.js';
import { colormap } from './colors.js';

export const POST_COLORS = { elastic: '#1a8c40', yielding: '#9933bf', failed: '#1a1a1a' };
export const BROKEN_CABLE = '#9a9a9a';
const BACKGROUND = '#eef2f6';

export function postState(status) {
  return status === 0 ? 'elastic' : status <= 2 ? 'yielding' : 'failed';
}

// The schematic body as in the PNG snapshots (src/io/out/figures.c): front face (crushed), rear, half
// width, face bottom and top, axles, wheels at their radius and axle height; body frame x forward, z up
// from the CG.
function body(v, crush) {
  const b = { xf: v.cg_to_front - crush, axle: [v.cg_to_front_axle, v.cg_to_front_axle - v.wheelbase], hw: 0.5 * v.front_width };
  b.xr = -v.cg_to_rear;
  b.zb = v.face_bottom - v.cg_height;
  b.zt = v.face_top - v.cg_height;
  b.wheelR = v.wheel_radius;
  b.wheelZ = v.wheel_radius - v.tyre_static_deflection - v.cg_height;
  return b;
}

// Text painted flat on the ground like a road marking, reading along +x, height h (m), centred at x, y.
function groundText(text, x, y, h, color = '#7d8470') {
  const c = document.createElement('canvas');
  const ctx = c.getContext('2d');
  const font = 'bold 64px system-ui, sans-serif';
  ctx.font = font;
  c.width = Math.ceil(ctx.measureText(text).width) + 16;
  c.height = 84;
  ctx.font = font;
  ctx.fillStyle = color;
  ctx.textBaseline = 'middle';
  ctx.fillText(text, 8, 44);
  const tex = new CanvasTexture(c);
  tex.colorSpace = SRGBColorSpace;
  tex.anisotropy = 4;
  const m = new Mesh(new PlaneGeometry((h * c.width) / c.height, h), new MeshBasicMaterial({ map: tex, transparent: true, depthWrite: false }));
  m.position.set(x, y, 0.01);
  return m;
}

// Build the replay in host (a sized element). Returns the controller, or throws if WebGL is missing.
export function createReplay(host, data, onFrame) {
  const frames = data.frames;
  const veh = data.vehicle;
  const posts = data.barrier.posts;
  const [a0, a1] = data.barrier.anchors;
  const ix = data.scenario.impact_x;
  let tmax = 0;
  for (const f of frames) for (const c of f[3]) for (const v of c[3]) tmax = Math.max(tmax, v);
  if (!(tmax > 0)) tmax = 1;

  const renderer = new WebGLRenderer({ antialias: true });
  renderer.setPixelRatio(Math.min(2, window.devicePixelRatio || 1));
  renderer.setClearColor(BACKGROUND);
  host.append(renderer.domElement);
  renderer.domElement.setAttribute('aria-label', '3D replay of the crash');

  const scene = new Scene();
  scene.background = new Color(BACKGROUND);
  scene.fog = new Fog(BACKGROUND, 120, 320);
  const camera = new PerspectiveCamera(38, 2, 0.1, 500);
  camera.up.set(0, 0, 1);
  scene.add(new HemisphereLight(0xffffff, 0x8a8a70, 1.6));
  scene.add(new AmbientLight(0xffffff, 0.4));
  const sun = new DirectionalLight(0xffffff, 1.6);
  sun.position.set(-20, -30, 40);
  scene.add(sun);

  // ground, a 2-m grid, the attack face (the cable line before impact), side labels
  const x0 = Math.min(a0[0], posts.length ? posts[0][0] : a0[0]) - 10;
  const x1 = Math.max(a1[0], posts.length ? posts[posts.length - 1][0] : a1[0]) + 10;
  const ground = new Mesh(new PlaneGeometry(x1 - x0 + 400, 400), new MeshLambertMaterial({ color: '#dfe3d3' }));
  ground.position.set(0.5 * (x0 + x1), 0, -0.01);
  scene.add(ground);
  const gridSize = 2 * Math.ceil((x1 - x0) / 4);
  const grid = new GridHelper(2 * gridSize, gridSize, '#b8bea8', '#b8bea8');
  grid.rotation.x = Math.PI / 2;
  grid.position.set(Math.round(0.5 * (x0 + x1) / 2) * 2, 0, 0.002);
  scene.add(grid);
  const faceLine = new Line(new BufferGeometry().setFromPoints([new Vector3(a0[0], 0, 0.01), new Vector3(a1[0], 0, 0.01)]), new LineDashedMaterial({ color: '#666', dashSize: 0.5, gapSize: 0.35 }));
  faceLine.computeLineDistances();
  scene.add(faceLine);
  scene.add(groundText('ATTACK SIDE', ix - 7, -2.2, 0.8));
  scene.add(groundText('PROTECTED SIDE', ix - 7, 4.5, 0.8));

  // anchors (dead-men) and posts
  const concrete = new MeshLambertMaterial({ color: '#a7a29a' });
  for (const a of [a0, a1]) {
    const m = new Mesh(new BoxGeometry(0.9, 0.9, 0.4), concrete);
    m.position.set(a[0], 0, Math.max(0.2, a[1]) - 0.2 + 0.001);
    scene.add(m);
  }
  const postGeom = new BoxGeometry(0.11, 0.11, 1).translate(0, 0, 0.5);
  const postMats = Object.fromEntries(Object.entries(POST_COLORS).map(([k, c]) => [k, new MeshLambertMaterial({ color: c })]));
  const postMeshes = posts.map((p) => {
    const m = new Mesh(postGeom, postMats.elastic);
    m.position.set(p[0], 0, 0);
    const footing = new Mesh(new BoxGeometry(0.35, 0.35, 0.04), concrete);
    footing.position.set(p[0], 0, 0.02);
    scene.add(footing);
    scene.add(m);
    return m;
  });

  // cables
  const cableMat = new LineMaterial({ linewidth: 4, vertexColors: true, worldUnits: false });
  const cableObjs = data.barrier.cables.map(() => {
    const l = new LineSegments2(new LineSegmentsGeometry(), cableMat);
    l.frustumCulled = false;
    scene.add(l);
    return l;
  });

  // the vehicle
  const v0 = body(veh, 0);
  const car = new Group();
  const bodyMesh = new Mesh(new BoxGeometry(1, 1, 1), new MeshLambertMaterial({ color: '#c9ccd1', transparent: true, opacity: 0.88 }));
  const bodyEdges = new LineSegments(new EdgesGeometry(new BoxGeometry(1, 1, 1)), new LineBasicMaterial({ color: '#555b66' }));
  const face = new Mesh(new BoxGeometry(0.08, 2 * v0.hw, v0.zt - v0.zb), new MeshLambertMaterial({ color: '#1d3f8f' }));
  car.add(bodyMesh, bodyEdges, face);
  const wheelGeom = new CylinderGeometry(v0.wheelR, v0.wheelR, 0.32, 24);
  const wheelMat = new MeshLambertMaterial({ color: '#333' });
  for (const ax of v0.axle)
    for (const side of [-1, 1]) {
      const w = new Mesh(wheelGeom, wheelMat);
      w.position.set(ax, side * (0.5 * veh.track || v0.hw * 0.85), v0.wheelZ);
      car.add(w);
    }
  scene.add(car);

  const controls = new OrbitControls(camera, renderer.domElement);
  controls.maxPolarAngle = Math.PI * 0.495;
  controls.addEventListener('change', () => requestRender());

  const views = {
    overview: () => [new Vector3(ix, 0.5, 0), new Vector3(ix - 11, -21, 13), 38],
    top: () => [new Vector3(ix, 1.5, 0), new Vector3(ix, 1.0, 34), 38],
    side: () => [new Vector3(ix, 0.5, 0.8), new Vector3(ix + 40, 0.5, 6), 18],
    driver: () => [new Vector3(ix, 3, 1.0), new Vector3(ix - 2.5, -12, 3.2), 45],
    front: () => [new Vector3(ix, 0, 0.8), new Vector3(ix + 7, 13, 4.5), 40],
  };
  function setView(name) {
    const [target, position, fov] = views[name]();
    camera.fov = fov;
    camera.updateProjectionMatrix();
    controls.target.copy(target);
    camera.position.copy(position);
    camera.lookAt(controls.target);
    controls.update();
    requestRender();
  }

  let follow = false;
  let frame = -1;
  const tmp = new Vector3();
  const zAxis = new Vector3(0, 0, 1);
  const q = new Quaternion();

  function showFrame(i) {
    i = Math.max(0, Math.min(frames.length - 1, i | 0));
    const f = frames[i];
    const [x, y, z, roll, pitch, yaw, crush] = f[1];
    const b = body(veh, crush);
    const before = car.position.clone();
    car.position.set(x, y, z);
    car.rotation.set(roll, pitch, yaw, 'ZYX');
    bodyMesh.scale.set(b.xf - b.xr, 2 * b.hw, b.zt - b.zb);
    bodyMesh.position.set(0.5 * (b.xf + b.xr), 0, 0.5 * (b.zt + b.zb));
    bodyEdges.scale.copy(bodyMesh.scale);
    bodyEdges.position.copy(bodyMesh.position);
    face.position.set(b.xf, 0, 0.5 * (b.zt + b.zb));
    if (follow && frame >= 0) {
      tmp.copy(car.position).sub(before);
      controls.target.add(tmp);
      camera.position.add(tmp);
      controls.update();
    }
    const pv = f[2];
    postMeshes.forEach((m, p) => {
      const top = tmp.set(pv[4 * p], pv[4 * p + 1], pv[4 * p + 2]).sub(m.position);
      const len = top.length();
      if (len > 1e-6) {
        q.setFromUnitVectors(zAxis, top.divideScalar(len));
        m.quaternion.copy(q);
        m.scale.set(1, 1, len);
      }
      m.material = postMats[postState(pv[4 * p + 3])];
    });
    f[3].forEach((c, k) => {
      const [status, , xyz, ten] = c;
      const n = xyz.length / 3;
      const pos = new Float32Array(Math.max(0, n - 1) * 6);
      const col = new Float32Array(Math.max(0, n - 1) * 6);
      const grey = new Color(BROKEN_CABLE);
      for (let j = 0; j + 1 < n; j++) {
        pos.set(xyz.slice(3 * j, 3 * j + 6), 6 * j);
        const cc = status === 1 || status === 2 ? grey : new Color(colormap(ten[j] / tmax));
        col.set([cc.r, cc.g, cc.b, cc.r, cc.g, cc.b], 6 * j);
      }
      const obj = cableObjs[k];
      obj.geometry.dispose();
      obj.geometry = new LineSegmentsGeometry();
      if (n > 1) {
        obj.geometry.setPositions(pos);
        obj.geometry.setColors(col);
      }
      obj.visible = n > 1;
    });
    frame = i;
    requestRender();
    onFrame(i);
  }

  let pending = false;
  function render() {
    pending = false;
    const w = renderer.domElement.clientWidth;
    const h = renderer.domElement.clientHeight;
    cableMat.resolution.set(w, h);
    renderer.render(scene, camera);
  }
  function requestRender() {
    if (!pending) {
      pending = true;
      requestAnimationFrame(render);
    }
  }
  function resize() {
    const w = host.clientWidth;
    const h = host.clientHeight;
    if (w < 10 || h < 10) return;
    renderer.setSize(w, h, true);
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
    requestRender();
  }
  const observer = new ResizeObserver(resize);
  observer.observe(host);
  resize();
  setView('overview');
  showFrame(0);

  return {
    tmax,
    showFrame,
    setView,
    setFollow(on) {
      follow = on;
    },
    get frame() {
      return frame;
    },
    // Let the WebGL context go (a page that replaces its replay: the designer's).
    dispose() {
      observer.disconnect();
      renderer.dispose();
      renderer.forceContextLoss();
      renderer.domElement.remove();
    },
    vehiclePosition() {
      return car.position.toArray();
    },
    // Render now and read the pixels back: how much of the picture differs from the background.
    readPixels() {
      render();
      const gl = renderer.getContext();
      const w = gl.drawingBufferWidth;
      const h = gl.drawingBufferHeight;
      const buf = new Uint8Array(w * h * 4);
      gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, buf);
      const bg = new Color(BACKGROUND);
      const br = Math.round(bg.r * 255);
      const bgG = Math.round(bg.g * 255);
      const bb = Math.round(bg.b * 255);
      let differ = 0;
      let hash = 2166136261;
      const colours = new Set();
      for (let i = 0; i < buf.length; i += 4) {
        if (Math.abs(buf[i] - br) + Math.abs(buf[i + 1] - bgG) + Math.abs(buf[i + 2] - bb) > 24) differ++;
        colours.add((buf[i] >> 4) | ((buf[i + 1] >> 4) << 4) | ((buf[i + 2] >> 4) << 8));
        hash = Math.imul(hash ^ buf[i] ^ (buf[i + 1] << 8) ^ (buf[i + 2] << 16), 16777619) >>> 0;
      }
      return { width: w, height: h, nonBackground: differ / (w * h), colours: colours.size, hash };
    },
  };
}
