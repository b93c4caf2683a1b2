// The agrirecipe page: prompt -> field table, map and 3D view; edits, refine, render, history.
// Every tab keeps its own current scene (in the URL's #scene=ID), so tabs work side by side.
import { Viewer } from '/static/viewer.js';

const $ = (id) => document.getElementById(id);
const fmt = (n) => Number(n).toLocaleString('en-US');
const state = { scene: null, choices: null, job: null, pending: 0 };
let viewer = null;

function el(tag, attrs = {}, ...children) {
  const node = document.createElement(tag);
  for (const [key, value] of Object.entries(attrs)) {
    if (key === 'class') node.className = value;
    else if (key === 'text') node.textContent = value;
    else if (key.startsWith('on')) node.addEventListener(key.slice(2), value);
    else if (value !== undefined && value !== null && value !== false) node.setAttribute(key, value === true ? '' : value);
  }
  for (const child of children) if (child !== null && child !== undefined) node.append(child);
  return node;
}

function busy(delta) {
  state.pending += delta;
  $('busy').hidden = state.pending <= 0;
}

/** Call the API; an error answer is shown as its message and hint, and rethrown. */
async function api(method, url, body) {
  busy(1);
  try {
    const options = { method, headers: {} };
    if (body !== undefined) {
      options.headers['Content-Type'] = 'application/json';
      options.body = JSON.stringify(body);
    }
    let response;
    try {
      response = await fetch(url, options);
    } catch (exc) {
      throw showError({ message: 'the app is not reachable', hint: 'is `agrirecipe app` still running?' });
    }
    const text = await response.text();
    let data = null;
    try { data = text ? JSON.parse(text) : null; } catch (exc) { data = null; }
    if (!response.ok) {
      throw showError((data && data.error) || { message: `the app answered ${response.status}`, hint: null });
    }
    hideError();
    return data;
  } finally {
    busy(-1);
  }
}

function showError(error) {
  $('error').hidden = false;
  $('error-message').textContent = error.message || 'something went wrong';
  $('error-hint').textContent = error.hint || '';
  $('error-hint').hidden = !error.hint;
  const list = $('error-problems');
  list.replaceChildren(...(error.problems || []).map(([path, message]) => el('li', { text: `${path}: ${message}` })));
  const exc = new Error(error.message);
  exc.shown = true;
  return exc;
}

function hideError() { $('error').hidden = true; }

function quietly(promise) { return promise.catch((exc) => { if (!exc.shown) showError({ message: String(exc) }); }); }

// --- the scene ---

function select(options, value, attrs) {
  const node = el('select', attrs);
  for (const option of options) {
    if (option.group) {
      const group = el('optgroup', { label: option.group });
      for (const item of option.items) group.append(el('option', { value: item, text: item, selected: item === value }));
      node.append(group);
    } else {
      node.append(el('option', { value: option, text: option, selected: option === value }));
    }
  }
  return node;
}

function editField(fieldId, update) {
  const id = state.scene.scene.id;
  return quietly(api('POST', `/api/scenes/${id}/fields/${fieldId}`, update).then(showScene));
}

function fieldRow(field) {
  const c = state.choices;
  const stated = new Set(field.stated);
  const attrs = (name) => ({
    'data-field': field.id, 'data-attr': name, class: stated.has(name) ? 'stated' : '',
    title: stated.has(name) ? 'stated in the request' : 'inferred from crop knowledge',
    onchange: (event) => editField(field.id, { [name]: event.target.value }),
  });
  const crops = Object.entries(c.categories).map(([group, items]) => ({ group, items }));
  const size = (axis) => el('input', {
    type: 'number', min: '0.5', step: 'any', value: field.size_m[axis], 'data-field': field.id,
    'data-attr': axis ? 'length' : 'width', class: stated.has('size') ? 'stated' : '',
    onchange: () => {
      const inputs = document.querySelectorAll(`input[data-field="${field.id}"]`);
      editField(field.id, { size_m: [Number(inputs[0].value), Number(inputs[1].value)] });
    },
  });
  const tags = el('div', { class: 'tags' },
    ...field.stated.map((a) => el('span', { class: 'tag', text: a })),
    ...field.inferred.map((a) => el('span', { class: 'tag inferred', text: a })));
  return el('tr', { 'data-field': field.id },
    el('td', {}, el('div', { class: 'swatch', style: `background:${field.colour}` })),
    el('td', { title: field.asset_path }, el('div', { class: 'id', text: field.id }), el('div', { class: 'meta', text: field.label })),
    el('td', {}, select(crops, field.crop, attrs('crop'))),
    el('td', {}, select(c.crops[field.crop].varieties, field.variety, attrs('variety'))),
    el('td', {}, select(c.stages, field.stage, attrs('stage'))),
    el('td', {}, select(c.seasons, field.season, attrs('season'))),
    el('td', {}, select(c.health, field.health, attrs('health'))),
    el('td', { class: 'size' }, size(0), ' × ', size(1)),
    el('td', { text: fmt(field.nominal_plant_count), title: `${field.rows} rows, ${field.row_spacing_m} m apart; a plant every ${field.in_row_spacing_m} m` }),
    el('td', {}, tags),
  );
}

function relationsEditor(desc) {
  const ids = desc.fields.map((f) => f.id);
  const box = $('relations');
  const rows = desc.relations.map((r) => ({ ...r, objects: [...r.objects] }));
  const render = () => {
    const items = rows.map((r, index) => {
      const subject = select(ids, r.subject, { onchange: (e) => { r.subject = e.target.value; } });
      const kind = select(state.choices.relation_kinds, r.kind, {
        onchange: (e) => {
          r.kind = e.target.value;
          r.objects = r.kind === 'between' ? [r.objects[0] || ids[0], r.objects[1] || ids[ids.length - 1]] : [r.objects[0]];
          render();
        },
      });
      const objects = r.objects.map((o, k) => select(ids, o, { onchange: (e) => { r.objects[k] = e.target.value; } }));
      return el('span', { class: 'relation' }, subject, kind, ...objects,
        el('button', { type: 'button', class: 'secondary', title: 'remove', text: '×', onclick: () => { rows.splice(index, 1); render(); } }));
    });
    const add = el('button', {
      type: 'button', class: 'secondary', text: '+ relation', disabled: ids.length < 2,
      onclick: () => { rows.push({ kind: 'next_to', subject: ids[0], objects: [ids[1]] }); render(); },
    });
    const apply = el('button', {
      type: 'button', text: 'Apply relations', id: 'apply-relations',
      onclick: () => quietly(api('PUT', `/api/scenes/${desc.scene.id}/relations`, { relations: rows }).then(showScene)),
    });
    box.replaceChildren(el('span', { class: 'meta', text: 'Relations:' }), ...items, add, apply);
  };
  render();
}

function showScene(desc) {
  state.scene = desc;
  const id = desc.scene.id;
  if (location.hash !== `#scene=${id}`) history.replaceState(null, '', `#scene=${id}`);
  $('empty').hidden = true;
  $('scene').hidden = false;
  $('refine').disabled = false;
  $('refine-apply').disabled = false;
  const fields = desc.fields.length;
  $('scene-title').textContent = `${fields} field${fields === 1 ? '' : 's'}`;
  $('scene-meta').textContent = `${fmt(desc.recipe.nominal_plant_count)} planting positions · ${desc.recipe.season} · `
    + `${desc.recipe.latitude_deg.toFixed(1)}° · seed ${desc.recipe.seed} · ${desc.recipe.resolver} · scene ${id}`;
  $('fields').tBodies[0].replaceChildren(...desc.fields.map(fieldRow));
  relationsEditor(desc);
  $('warnings').replaceChildren(...desc.warnings.map((w) => el('li', { text: w })));
  $('map').src = `/api/scenes/${id}/files/${desc.map}`;
  $('download').href = `/api/scenes/${id}/download`;
  $('changes').replaceChildren(...desc.scene.changes.map((c) => el('li', { text: c })));
  $('explanation').replaceChildren(...desc.explanation.map((stage) => el('div', { class: 'stage' },
    el('h3', { text: stage.stage }), el('ul', {}, ...stage.lines.map((line) => el('li', { text: line }))))));
  $('render-image').hidden = true;
  $('render-progress').hidden = true;
  if (viewer) quietly(viewer.load(id));
  refreshHistory();
  return desc;
}

async function openScene(id) {
  return quietly(api('GET', `/api/scenes/${id}`).then(showScene));
}

async function refreshHistory() {
  const data = await api('GET', '/api/history?limit=30').catch(() => null);
  if (!data) return;
  const current = state.scene && state.scene.scene.id;
  $('history').replaceChildren(...data.scenes.map((s) => el('li', {
    class: s.id === current ? 'current' : '', 'data-scene': s.id, title: s.text, onclick: () => openScene(s.id),
  }, el('span', { class: 'what', text: `${s.action === 'prompt' ? '' : s.action + ': '}${s.text}` }),
  el('span', { class: 'when', text: `${s.summary} · ${fmt(s.plant_count)} plants · ${s.created.replace('T', ' ').slice(0, 16)}` }))));
}

// --- render ---

async function startRender() {
  const [width, height] = $('render-size').value.split('x').map(Number);
  const body = { width, height, samples: Number($('render-samples').value), view: $('render-view').value };
  const job = await api('POST', `/api/scenes/${state.scene.scene.id}/render`, body);
  state.job = job.id;
  $('render-cancel').hidden = false;
  $('render').disabled = true;
  $('render-image').hidden = true;
  pollRender(job);
}

function pollRender(job) {
  const bar = $('render-progress');
  bar.hidden = false;
  bar.querySelector('.bar').style.width = `${Math.round(job.progress * 100)}%`;
  bar.querySelector('.label').textContent = `${Math.round(job.progress * 100)} % · ${job.message}`;
  if (job.state === 'queued' || job.state === 'running') {
    setTimeout(() => api('GET', `/api/renders/${job.id}`).then(pollRender).catch(() => finishRender()), 700);
    return;
  }
  finishRender();
  if (job.state === 'done') {
    const image = $('render-image');
    image.src = `/api/scenes/${job.scene_id}/files/${job.image}?t=${Date.now()}`;
    image.hidden = false;
    bar.querySelector('.label').textContent = `rendered in ${job.seconds} s`;
  } else if (job.state === 'failed') {
    showError({ message: job.error || 'Blender failed', hint: 'try fewer samples or a smaller size' });
  }
}

function finishRender() {
  state.job = null;
  $('render-cancel').hidden = true;
  $('render').disabled = false;
}

// --- wiring ---

async function start() {
  const [choices, examples] = await Promise.all([api('GET', '/api/choices'), api('GET', '/api/examples')]);
  state.choices = choices;
  $('examples').replaceChildren(...examples.prompts.map((p) => el('button', {
    type: 'button', text: p, onclick: () => { $('prompt').value = p; $('prompt-count').textContent = p.length; },
  })));
  $('refine-examples').replaceChildren(...examples.refinements.map((p) => el('button', {
    type: 'button', text: p, onclick: () => { $('refine').value = p; },
  })));
  $('prompt').addEventListener('input', () => { $('prompt-count').textContent = fmt($('prompt').value.length); });
  $('prompt-form').addEventListener('submit', (event) => {
    event.preventDefault();
    $('make').disabled = true;
    quietly(api('POST', '/api/scenes', { prompt: $('prompt').value }).then(showScene))
      .finally(() => { $('make').disabled = false; });
  });
  $('prompt').addEventListener('keydown', (event) => {
    if (event.key === 'Enter' && (event.ctrlKey || event.metaKey)) $('prompt-form').requestSubmit();
  });
  $('refine-form').addEventListener('submit', (event) => {
    event.preventDefault();
    const id = state.scene.scene.id;
    quietly(api('POST', `/api/scenes/${id}/refine`, { instruction: $('refine').value }).then((desc) => {
      $('refine').value = '';
      return showScene(desc);
    }));
  });
  $('upload').addEventListener('change', async (event) => {
    const file = event.target.files[0];
    if (!file) return;
    const text = await file.text();
    event.target.value = '';
    quietly(api('POST', '/api/scenes/upload', { recipe: text }).then(showScene));
  });
  $('render').addEventListener('click', () => quietly(startRender()));
  $('render-cancel').addEventListener('click', () => {
    if (state.job) quietly(api('POST', `/api/renders/${state.job}/cancel`));
  });
  try {
    viewer = new Viewer($('canvas3d'), $('view-status'));
  } catch (exc) {
    $('view-status').textContent = `3D view unavailable: ${exc.message}`;
  }
  window.agrirecipeViewer = viewer;
  $('reset-view').addEventListener('click', () => viewer && viewer.overview());
  $('walk').addEventListener('click', () => {
    if (!viewer) return;
    if (viewer.walkState) { viewer.stopWalk(); return; }
    if (viewer.walk(() => { $('walk').textContent = 'Walk along the row'; })) $('walk').textContent = 'Stop walking';
  });
  refreshHistory();
  // Only now can a request be made: a click before the handlers were attached would
  // submit the form natively and reload the page (the prompt lost).
  $('make').disabled = false;
  document.body.dataset.ready = 'yes';
  const match = location.hash.match(/scene=([0-9a-f]{12})/);
  if (match) openScene(match[1]);
}

quietly(start());
