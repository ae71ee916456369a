// The oracle's half of the rig conformance suite: a model file loaded with
// three.js's own loaders (GLTFLoader, FBXLoader, ColladaLoader) in Node,
// posed by an AnimationMixer, every vertex of every mesh read back in the
// scene's world space, skin and morph targets applied as three.js applies
// them (Mesh / SkinnedMesh.getVertexPosition).
import fs from 'node:fs';
import path from 'node:path';

import { DOMParser } from '@xmldom/xmldom';
import { AnimationMixer, LoadingManager, Matrix4, Mesh, SkinnedMesh, Vector3 } from 'three';
import { ColladaLoader } from 'three/addons/loaders/ColladaLoader.js';
import { FBXLoader } from 'three/addons/loaders/FBXLoader.js';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';

// ColladaLoader parses XML with the browser's DOMParser; xmldom is one for
// Node. It has no querySelector, which the loader calls only to find an
// element by its id or sid attribute ('[id="x"]'): that one form is added.
function addAttributeQuery(document) {
  const proto = Object.getPrototypeOf(document.documentElement);
  if (proto.querySelector) return;
  proto.querySelector = function querySelector(selector) {
    const match = /^\[(\w+)="(.*)"\]$/.exec(selector);
    if (!match) throw new Error(`querySelector: only [attribute="value"] is supported, not ${selector}`);
    const [, name, value] = match;
    const stack = [this];
    while (stack.length > 0) {
      const node = stack.pop();
      for (let i = node.childNodes.length - 1; i >= 0; i--) {
        const child = node.childNodes[i];
        if (child.nodeType !== 1) continue;
        if (child.getAttribute(name) === value) return child;
        stack.push(child);
      }
    }
    return null;
  };
}

class XmlDomParser {
  parseFromString(text, type) {
    const document = new DOMParser().parseFromString(text, type);
    addAttributeQuery(document);
    return document;
  }
}

function arrayBufferOf(bytes) {
  return bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength);
}

// A .gltf's buffers beside it: Node's fetch, which the loaders use, reads
// no file: URLs, so each is handed over as a data: URL of the file.
// FileLoader reports its progress with the browser's ProgressEvent, which
// Node lacks: an Event carrying the same three numbers stands in.
globalThis.ProgressEvent ??= class ProgressEvent extends Event {
  constructor(type, { lengthComputable = false, loaded = 0, total = 0 } = {}) {
    super(type);
    Object.assign(this, { lengthComputable, loaded, total });
  }
};

function filesBeside(folder) {
  const manager = new LoadingManager();
  manager.setURLModifier((url) => {
    if (/^(data|https?):/.test(url)) return url;
    const bytes = fs.readFileSync(path.resolve(folder, decodeURIComponent(url)));
    return `data:application/octet-stream;base64,${bytes.toString('base64')}`;
  });
  return manager;
}

// three.js skins with four influences per vertex (skinIndex, skinWeight);
// GLTFLoader keeps a file's further sets (JOINTS_1, WEIGHTS_1) as the
// attributes joints_1 and weights_1 and scales the first set alone to a
// sum of 1. To pose a file's eight influences, three's own sum
// (SkinnedMesh.applyBoneTransform: each joint's bone.matrixWorld times its
// bone inverse, weighted) is taken over every set, with the file's first
// weights, kept here before GLTFLoader rescales them.
const fileWeights = new WeakMap();  // skinWeight attribute → the file's values
const normalizeSkinWeights = SkinnedMesh.prototype.normalizeSkinWeights;
SkinnedMesh.prototype.normalizeSkinWeights = function keepFileWeights() {
  const weights = this.geometry.attributes.skinWeight;
  if (!fileWeights.has(weights)) fileWeights.set(weights, weightValues(weights));
  normalizeSkinWeights.call(this);
};

// An attribute's values as numbers (a normalised integer attribute read
// as 0..1).
function weightValues(attribute) {
  const values = new Float64Array(4 * attribute.count);
  for (let i = 0; i < attribute.count; i++) {
    for (let c = 0; c < 4; c++) values[4 * i + c] = attribute.getComponent(i, c);
  }
  return values;
}

function influenceSets(mesh) {
  const geometry = mesh.geometry;
  if (!mesh.isSkinnedMesh || !geometry.attributes.joints_1) return null;
  const sets = [{ joints: geometry.attributes.skinIndex, weights: fileWeights.get(geometry.attributes.skinWeight) }];
  for (let k = 1; geometry.attributes[`joints_${k}`]; k++) {
    sets.push({ joints: geometry.attributes[`joints_${k}`], weights: weightValues(geometry.attributes[`weights_${k}`]) });
  }
  return sets;
}

const jointMatrix = new Matrix4();
const bindPosition = new Vector3();
const moved = new Vector3();

// Vertex i of a skinned mesh with more than four influences, as three's
// applyBoneTransform poses four, the weights taken over by their total.
function positionOverAllSets(mesh, sets, i, target) {
  Mesh.prototype.getVertexPosition.call(mesh, i, target);  // base and morph targets
  bindPosition.copy(target).applyMatrix4(mesh.bindMatrix);
  target.set(0, 0, 0);
  let total = 0;
  for (const { joints, weights } of sets) {
    for (let c = 0; c < 4; c++) {
      const weight = weights[4 * i + c];
      if (weight === 0) continue;
      const bone = joints.getComponent(i, c);
      jointMatrix.multiplyMatrices(mesh.skeleton.bones[bone].matrixWorld, mesh.skeleton.boneInverses[bone]);
      target.addScaledVector(moved.copy(bindPosition).applyMatrix4(jointMatrix), weight);
      total += weight;
    }
  }
  return target.multiplyScalar(1 / total).applyMatrix4(mesh.bindMatrixInverse);
}

// The scene and its clips, as a page using the loader would get them.
async function loadScene(file) {
  const bytes = fs.readFileSync(file);
  const folder = path.dirname(file) + path.sep;
  const extension = path.extname(file).toLowerCase();
  if (extension === '.glb' || extension === '.gltf') {
    const gltf = await new Promise((resolve, reject) =>
      new GLTFLoader(filesBeside(folder)).parse(arrayBufferOf(bytes), '', resolve, reject));
    return { root: gltf.scene, clips: gltf.animations };
  }
  if (extension === '.fbx') {
    const root = new FBXLoader().parse(arrayBufferOf(bytes), folder);
    return { root, clips: root.animations };
  }
  if (extension === '.dae') {
    globalThis.DOMParser = XmlDomParser;
    const collada = new ColladaLoader().parse(bytes.toString('utf8'), folder);
    return { root: collada.scene, clips: collada.scene.animations };
  }
  throw new Error(`three_pose: no three.js loader for ${file}`);
}

export class ThreeModel {
  static async load(file) {
    const { root, clips } = await loadScene(file);
    root.updateMatrixWorld(true);
    const meshes = [];
    root.traverse((object) => {
      if (object.isMesh && object.geometry.attributes.position) meshes.push(object);
    });
    return new ThreeModel(root, clips, meshes);
  }

  constructor(root, clips, meshes) {
    this.root = root;
    this.clips = clips;
    this.meshes = meshes;
    this.vertexCount = meshes.reduce((n, mesh) => n + mesh.geometry.attributes.position.count, 0);
    this.rest = this.#placedVertices((mesh, i, v) => v.fromBufferAttribute(mesh.geometry.attributes.position, i));
    this.mixer = new AnimationMixer(root);
    this.playing = null;
  }

  clip(name) {
    const clip = this.clips.find((c) => c.name === name);
    if (!clip) throw new Error(`three.js found no clip "${name}"; it has ${this.clips.map((c) => `"${c.name}"`).join(', ')}`);
    return clip;
  }

  // Every vertex as the file stores it (no skin, no morph), placed by its
  // mesh's world matrix before any clip plays: the bind geometry, which is
  // what toond's import keeps as its rest positions.
  restPositions() {
    return this.rest;
  }

  // Every vertex at `time` seconds of `clip`: AnimationMixer.setTime plays
  // the clip from 0 to `time` (a looping action: a time past the clip's
  // duration wraps round, a negative one counts back from the end), then
  // each vertex is skinned and morphed as three.js draws it.
  posedPositions(clip, time) {
    const action = this.mixer.clipAction(clip);
    if (this.playing !== action) {
      this.mixer.stopAllAction();
      action.play();
      this.playing = action;
    }
    this.mixer.setTime(time);
    this.root.updateMatrixWorld(true);
    const sets = new Map(this.meshes.map((mesh) => [mesh, influenceSets(mesh)]));
    return this.#placedVertices((mesh, i, v) =>
      sets.get(mesh) ? positionOverAllSets(mesh, sets.get(mesh), i, v) : mesh.getVertexPosition(i, v));
  }

  // vertex(mesh, i, v) fills v in the mesh's own space; the result is every
  // vertex of every mesh in the world, x y z after each other.
  #placedVertices(vertex) {
    const out = new Float64Array(3 * this.vertexCount);
    const v = new Vector3();
    let at = 0;
    for (const mesh of this.meshes) {
      const count = mesh.geometry.attributes.position.count;
      for (let i = 0; i < count; i++, at += 3) {
        vertex(mesh, i, v).applyMatrix4(mesh.matrixWorld);
        out[at] = v.x;
        out[at + 1] = v.y;
        out[at + 2] = v.z;
      }
    }
    return out;
  }
}
