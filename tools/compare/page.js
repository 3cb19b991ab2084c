// The comparison page: one WebGL canvas behind a grid of panels, each panel
// a scene drawn into its own rectangle, every panel seen by the same camera.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

const data = JSON.parse(document.getElementById('subdiv-data').textContent);

function decode(base64, Type) {
  const text = atob(base64);
  const bytes = new Uint8Array(text.length);
  for (let i = 0; i < text.length; ++i) bytes[i] = text.charCodeAt(i);
  return new Type(bytes.buffer);
}

function lines(positions, edges, colour) {
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
  geometry.setIndex(new THREE.BufferAttribute(edges, 1));
  return new THREE.LineSegments(geometry, new THREE.LineBasicMaterial({ color: colour }));
}

const canvas = document.getElementById('canvas');
const renderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
renderer.setPixelRatio(window.devicePixelRatio);
renderer.setScissorTest(true);
const background = new THREE.Color(0xffffff);

const centre = new THREE.Vector3(...data.centre);
const radius = data.radius > 0 ? data.radius : 1;
const camera = new THREE.PerspectiveCamera(30, 1, radius * 0.01, radius * 100);
const azimuth = THREE.MathUtils.degToRad(30), elevation = THREE.MathUtils.degToRad(20);
const distance = 1.04 * radius / Math.sin(THREE.MathUtils.degToRad(15));
camera.position.set(centre.x + distance * Math.cos(elevation) * Math.sin(azimuth),
                    centre.y + distance * Math.sin(elevation),
                    centre.z + distance * Math.cos(elevation) * Math.cos(azimuth));

const cagePositions = decode(data.cage.positions, Float32Array);
const cageEdges = decode(data.cage.edges, Uint32Array);
const container = document.getElementById('panels');
const panels = data.panels.map((panel) => {
  const element = document.createElement('div');
  element.className = 'panel';
  const view = document.createElement('div');
  view.className = 'view';
  const caption = document.createElement('div');
  caption.className = 'caption';
  const title = document.createElement('b');
  title.textContent = panel.title;
  caption.append(title, document.createElement('br'), panel.caption);
  element.append(view, caption);
  container.append(element);

  const scene = new THREE.Scene();
  scene.background = background;
  const positions = decode(panel.positions, Float32Array);
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
  geometry.setIndex(new THREE.BufferAttribute(decode(panel.triangles, Uint32Array), 1));
  geometry.computeVertexNormals();
  const material = new THREE.MeshPhongMaterial({
    color: 0xb8c2d1, specular: 0x333333, shininess: 40, side: THREE.DoubleSide,
    polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1,
  });
  scene.add(new THREE.Mesh(geometry, material));
  const wire = lines(positions, decode(panel.edges, Uint32Array), 0x1f1f24);
  const cage = lines(cagePositions, cageEdges, 0x0d9933);
  scene.add(wire, cage);
  scene.add(new THREE.AmbientLight(0xffffff, 0.35));
  const light = new THREE.DirectionalLight(0xffffff, 2.2);
  scene.add(light);
  return { view, scene, wire, cage, light };
});

const wireframe = document.getElementById('wireframe');
const showCage = document.getElementById('cage');
const controls = new OrbitControls(camera, container);
controls.target.copy(centre);
controls.update();

function render() {
  const width = canvas.clientWidth, height = canvas.clientHeight;
  if (canvas.width !== Math.floor(width * window.devicePixelRatio) ||
      canvas.height !== Math.floor(height * window.devicePixelRatio))
    renderer.setSize(width, height, false);
  renderer.setScissor(0, 0, width, height);
  renderer.setClearColor(0xf4f4f4);
  renderer.clear();
  for (const panel of panels) {
    panel.wire.visible = wireframe.checked;
    panel.cage.visible = showCage.checked;
    // The key light sits up and to the left of the camera, as in `subdiv render`.
    panel.light.position.copy(camera.position).add(camera.up.clone().multiplyScalar(distance))
      .sub(new THREE.Vector3().crossVectors(camera.getWorldDirection(new THREE.Vector3()), camera.up)
        .multiplyScalar(distance * 0.6));
    const rect = panel.view.getBoundingClientRect();
    if (rect.bottom < 0 || rect.top > height || rect.right < 0 || rect.left > width) continue;
    const bottom = height - rect.bottom;
    renderer.setViewport(rect.left, bottom, rect.width, rect.height);
    renderer.setScissor(rect.left, bottom, rect.width, rect.height);
    camera.aspect = rect.width / rect.height;
    camera.updateProjectionMatrix();
    renderer.render(panel.scene, camera);
  }
}

controls.addEventListener('change', render);
wireframe.addEventListener('change', render);
showCage.addEventListener('change', render);
window.addEventListener('resize', render);
window.addEventListener('scroll', render);
render();
document.body.dataset.ready = 'true';
