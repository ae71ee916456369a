// The materials section: for a stored model (GET /models/{id} lists its
// material_list), each material's name, the image it is drawn with and how
// its alpha is drawn, as the file and its format's engine say; a selector
// per material overrides the alpha for this request (`materials.<name>.alpha`).
const ALPHA_CHOICES = ['opaque', 'mask', 'blend'];

export class MaterialList {
  // `root` holds #material-table; `hooks.get(name)` is the request's
  // `materials.<name>` (or undefined), `hooks.setAlpha(name, alpha)` sets
  // its alpha (undefined: as the file says).
  constructor(root, hooks) {
    this.root = root;
    this.hooks = hooks;
    this.table = root.querySelector('#material-table');
    this.modelId = null;
    this.cache = new Map();
    this.materials = [];
  }

  // The model shown changed (or may have): fetch its materials, once per id.
  async showModel(id) {
    if (id === this.modelId) return;
    this.modelId = id;
    let materials = [];
    if (id) {
      if (!this.cache.has(id)) {
        const res = await fetch(`/models/${id}`).catch(() => null);
        const info = res && res.ok ? await res.json().catch(() => null) : null;
        this.cache.set(id, info?.material_list ?? []);
      }
      materials = this.cache.get(id);
    }
    if (id !== this.modelId) return;  // another model was chosen meanwhile
    this.materials = materials;
    this.root.hidden = materials.length === 0;
    this.render();
  }

  render() {
    const head = document.createElement('tr');
    for (const title of ['Material', 'Image', 'Alpha']) {
      const th = document.createElement('th');
      th.textContent = title;
      head.append(th);
    }
    const rows = this.materials.map((m) => this.row(m));
    this.table.replaceChildren(head, ...rows);
  }

  row(material) {
    const tr = document.createElement('tr');
    const name = document.createElement('td');
    name.textContent = material.name + (material.matte ? ' (matte)' : '');
    const image = document.createElement('td');
    image.textContent = material.texture || '—';
    const alpha = document.createElement('td');
    const select = document.createElement('select');
    select.setAttribute('aria-label', `${material.name}: alpha`);
    const fileSays = material.alpha === 'mask' ? `mask ${material.alpha_cutoff}` : material.alpha;
    select.append(new Option(`${fileSays} (file)`, ''), ...ALPHA_CHOICES.map((a) => new Option(a, a)));
    select.value = this.hooks.get(material.name)?.alpha ?? '';
    select.addEventListener('change', () => this.hooks.setAlpha(material.name, select.value || undefined));
    alpha.append(select);
    tr.append(name, image, alpha);
    return tr;
  }

  // Shows the request's overrides.
  sync() {
    for (const select of this.table.querySelectorAll('select')) {
      const name = select.getAttribute('aria-label').replace(/: alpha$/, '');
      select.value = this.hooks.get(name)?.alpha ?? '';
    }
  }
}
