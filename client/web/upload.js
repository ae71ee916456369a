// Model upload: files or a whole folder, from a drop or a picker, sent as
// one multipart POST /models where each part's filename is the file's path
// inside the bundle (spot.obj, textures/spot.png).

// Reads a dropped folder tree through the entries API (a plain
// DataTransfer.files lists a dropped folder as one useless entry).
async function filesOfEntry(entry, prefix, out) {
  if (entry.isFile) {
    const file = await new Promise((resolve, reject) => entry.file(resolve, reject));
    out.push({ file, path: prefix + file.name });
  } else if (entry.isDirectory) {
    const reader = entry.createReader();
    // readEntries answers in batches until it answers an empty one.
    for (;;) {
      const batch = await new Promise((resolve, reject) => reader.readEntries(resolve, reject));
      if (batch.length === 0) break;
      for (const child of batch) await filesOfEntry(child, prefix + entry.name + '/', out);
    }
  }
}

export async function filesFromDrop(dataTransfer) {
  const entries = [...dataTransfer.items]
    .map((item) => (item.webkitGetAsEntry ? item.webkitGetAsEntry() : null))
    .filter(Boolean);
  if (entries.length === 0) return [...dataTransfer.files].map((file) => ({ file, path: file.name }));
  const out = [];
  for (const entry of entries) await filesOfEntry(entry, '', out);
  return out;
}

// A folder picker names files "spot/spot.obj"; plain multiple selection "spot.obj".
export function filesFromInput(fileList) {
  return [...fileList].map((file) => ({ file, path: file.webkitRelativePath || file.name }));
}

// Paths inside the bundle are relative to the folder that holds the OBJ:
// the folder the user dropped ("spot/") is not part of them, and files
// outside that folder (a README beside it) are left out.
// The model files' extensions: toond's own readers', then those read
// through assimp (common/bundle_paths/model_formats.cpp; a unit test keeps
// the two lists equal).
export const MODEL_EXTENSIONS = [
  'obj', 'm', 'gltf', 'glb', 'stl', 'ply', 'iqm',
  'fbx', 'dae', 'zae', '3ds', '3mf', 'off', 'x', 'x3d', 'x3db', 'ase', 'ask',
  'ac', 'ac3d', 'acc', 'amf', 'b3d', 'cob', 'dxf', 'hmp', 'ifc', 'ifczip', 'irrmesh',
  'lwo', 'lxo', 'md2', 'md3', 'md5mesh', 'md5anim', 'mdc', 'mdl', 'ms3d', 'ndo',
  'nff', 'enff', 'ogex', 'pmx', 'q3o', 'q3s', 'sib', 'smd', 'xgl', 'bvh',
];
export const MODEL_FILE = new RegExp('\\.(' + MODEL_EXTENSIONS.join('|') + ')$', 'i');

export function bundlePaths(files) {
  const objs = files.filter((f) => MODEL_FILE.test(f.path));
  if (objs.length === 0) {
    throw new Error('no model file (.obj, .gltf, .glb, .stl, .ply, .fbx, .dae, .3ds, .3mf, .off, ...) among the ' +
      files.length + ' dropped');
  }
  const shallowest = objs.map((f) => f.path).sort((a, b) => a.split('/').length - b.split('/').length)[0];
  const base = shallowest.includes('/') ? shallowest.slice(0, shallowest.lastIndexOf('/') + 1) : '';
  return files
    .filter((f) => f.path.startsWith(base))
    .map((f) => ({ file: f.file, path: f.path.slice(base.length) }))
    // Licence texts and notes are not part of a model.
    .filter((f) => !/\.(txt|md|pdf|html?)$/i.test(f.path));
}

// Resolves with the upload answer ({id, triangles, ...}); onProgress(0..1).
export function uploadBundle(files, onProgress) {
  const form = new FormData();
  for (const { file, path } of files) form.append('file', file, path);
  return new Promise((resolve, reject) => {
    const xhr = new XMLHttpRequest();
    xhr.open('POST', '/models');
    xhr.responseType = 'json';
    xhr.upload.addEventListener('progress', (e) => {
      if (e.lengthComputable) onProgress(e.loaded / e.total);
    });
    xhr.addEventListener('load', () => {
      if (xhr.status === 200 || xhr.status === 201) {
        onProgress(1);
        resolve(xhr.response);
      } else {
        const e = xhr.response?.error ?? {};
        const error = new Error(e.message || `upload failed: HTTP ${xhr.status}`);
        error.path = e.path;
        reject(error);
      }
    });
    xhr.addEventListener('error', () => reject(new Error('upload failed: the server could not be reached')));
    xhr.send(form);
  });
}
