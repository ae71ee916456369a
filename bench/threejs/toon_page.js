// The same scene as toond's comparison render: the bunny framed like
// toond frames it (fov 35°, bounding sphere with a 1.08 margin), a light
// from the camera's side, three bands, a black outline, white background.
import * as THREE from 'three';
import { OBJLoader } from 'three/addons/loaders/OBJLoader.js';
import { OutlineEffect } from 'three/addons/effects/OutlineEffect.js';
import { mergeVertices } from 'three/addons/utils/BufferGeometryUtils.js';

const query = new URLSearchParams(location.search);
const size = Number(query.get('size') || 512);
const antialias = query.get('aa') === '1';
const modelUrl = query.get('model');

const renderer = new THREE.WebGLRenderer({ antialias, preserveDrawingBuffer: true });
renderer.setPixelRatio(1);
renderer.setSize(size, size);
document.body.appendChild(renderer.domElement);

const scene = new THREE.Scene();
scene.background = new THREE.Color(0xffffff);

// Three bands: a 3-texel gradient map, nearest filtering.
const gradient = new THREE.DataTexture(new Uint8Array([90, 170, 255]), 3, 1, THREE.RedFormat);
gradient.minFilter = THREE.NearestFilter;
gradient.magFilter = THREE.NearestFilter;
gradient.needsUpdate = true;
const material = new THREE.MeshToonMaterial({ color: 0xcccccc, gradientMap: gradient });

const group = await new OBJLoader().loadAsync(modelUrl);
let triangles = 0;
const box = new THREE.Box3();
group.traverse((o) => {
  if (!o.isMesh) return;
  // OBJ without normals: weld by position, then smooth normals (as toond does).
  const g = mergeVertices(o.geometry.deleteAttribute('normal').deleteAttribute('uv'));
  g.computeVertexNormals();
  o.geometry = g;
  o.material = material;
  triangles += g.index ? g.index.count / 3 : g.attributes.position.count / 3;
});
box.setFromObject(group);
scene.add(group);

const centre = box.getCenter(new THREE.Vector3());
const radius = box.getSize(new THREE.Vector3()).length() / 2;
const fov = 35;
const camera = new THREE.PerspectiveCamera(fov, 1, radius * 0.01, radius * 10);
const distance = (radius * 1.08) / Math.sin(THREE.MathUtils.degToRad(fov / 2));
camera.position.copy(centre).add(new THREE.Vector3(0, 0, distance));
camera.lookAt(centre);
scene.add(new THREE.AmbientLight(0xffffff, 0.3));
const sun = new THREE.DirectionalLight(0xffffff, 1.0);
sun.position.set(centre.x + radius, centre.y + radius, centre.z + distance);
sun.target.position.copy(centre);
scene.add(sun, sun.target);

const effect = new OutlineEffect(renderer, { defaultThickness: 0.004, defaultColor: [0, 0, 0] });
const canvas = renderer.domElement;
const toPng = () => new Promise((resolve) => canvas.toBlob(resolve, 'image/png'));

async function frame() {
  const t0 = performance.now();
  effect.render(scene, camera);
  const blob = await toPng();
  return { ms: performance.now() - t0, bytes: blob.size };
}

function glRenderer() {
  const gl = renderer.getContext();
  const info = gl.getExtension('WEBGL_debug_renderer_info');
  return info ? gl.getParameter(info.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER);
}

window.runBench = async (frames) => {
  for (let i = 0; i < 3; ++i) await frame();  // compile, upload, warm caches
  const times = [];
  let bytes = 0;
  for (let i = 0; i < frames; ++i) {
    const f = await frame();
    times.push(f.ms);
    bytes = f.bytes;
  }
  times.sort((a, b) => a - b);
  const at = (q) => times[Math.min(times.length - 1, Math.ceil(q * times.length) - 1)];
  return {
    median_ms: times.length % 2 ? times[(times.length - 1) / 2] : (times[times.length / 2 - 1] + times[times.length / 2]) / 2,
    p90_ms: at(0.9),
    frames,
    png_bytes: bytes,
    triangles,
    antialias,
    samples: renderer.getContext().getParameter(renderer.getContext().SAMPLES),
    renderer: glRenderer(),
    png: canvas.toDataURL('image/png'),
  };
};
window.benchReady = true;
