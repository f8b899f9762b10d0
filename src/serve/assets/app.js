// The review app of mtcs serve: projects, components and their versions, interference checks run
// on the server with their findings and 3-D view, review items with comments and viewpoints,
// and every change of the other members live (Server-Sent Events). User text reaches the page
// through textContent only. window.mtcsReview lets tests drive and read it.
const $ = (id) => document.getElementById(id);
const state = { csrf: '', user: null, project: null, role: null, jobs: [], topics: [], job: null, topic: null, events: null, lastEvent: 0 };
const ROLES = ['viewer', 'reviewer', 'designer', 'owner'];
const atLeast = (role) => ROLES.indexOf(state.role) >= ROLES.indexOf(role);

function el(tag, props = {}, children = []) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(props)) {
    if (k === 'text') e.textContent = v;
    else if (k === 'on') for (const [ev, f] of Object.entries(v)) e.addEventListener(ev, f);
    else e.setAttribute(k, v);
  }
  e.append(...children);
  return e;
}

async function api(method, path, body, type = 'application/json') {
  const headers = {};
  if (method !== 'GET') headers['X-MTCS-CSRF'] = state.csrf;
  if (body !== undefined) headers['Content-Type'] = type;
  const r = await fetch(path, { method, headers, body: body === undefined ? undefined : type === 'application/json' ? JSON.stringify(body) : body, credentials: 'same-origin' });
  const data = await r.json().catch(() => ({}));
  if (!r.ok) throw new Error(data.error || `${r.status}`);
  return data;
}
const show = (error) => { $('error').textContent = error ? String(error.message || error) : ''; };
const projectPath = (tail = '') => `/api/v1/projects/${state.project}${tail}`;

// ------------------------------------------------------------------ sign-in and projects
async function start() {
  try {
    const me = await api('GET', '/api/v1/me');
    state.csrf = me.csrf || '', state.user = me.user;
    signedIn();
  } catch { $('sign-in-panel').hidden = false; }
}
$('sign-in').addEventListener('submit', async (e) => {
  e.preventDefault();
  try {
    const me = await api('POST', '/api/v1/login', { name: $('name').value, password: $('password').value });
    state.csrf = me.csrf, state.user = me.user;
    $('sign-in-error').textContent = '';
    signedIn();
  } catch (err) { $('sign-in-error').textContent = err.message; }
});
$('sign-out').addEventListener('click', async () => { await api('POST', '/api/v1/logout', {}); location.reload(); });

async function signedIn() {
  $('sign-in-panel').hidden = true;
  $('who').textContent = `signed in as ${state.user}`;
  $('sign-out').hidden = false;
  $('projects-panel').hidden = false;
  await listProjects();
}
async function listProjects() {
  const projects = await api('GET', '/api/v1/projects');
  $('projects').replaceChildren(...projects.map((p) => el('li', {}, [
    el('a', { href: `#project-${p.id}`, text: p.name, on: { click: () => openProject(p.id) } }), ` (${p.role})`])));
  $('new-project').hidden = false;
  const wanted = /^#project-(\d+)/.exec(location.hash);
  if (wanted && !state.project) openProject(Number(wanted[1]));
}
$('new-project').addEventListener('submit', async (e) => {
  e.preventDefault();
  try { const p = await api('POST', '/api/v1/projects', { name: $('project-name').value }); await listProjects(); openProject(p.id); } catch (err) { show(err); }
});

async function openProject(id) {
  state.project = id;
  const p = await api('GET', projectPath());
  state.role = p.role;
  state.lastEvent = p.last_event;  // the lists below are as of now: the stream starts after it
  $('project-panel').hidden = false;
  $('project-title').textContent = p.name;
  $('project-role').textContent = `your role: ${p.role} \u00b7 members: ${p.members.map((m) => `${m.user} (${m.role})`).join(', ')}`;
  $('export-bcf').setAttribute('href', projectPath('/bcf'));
  for (const f of document.querySelectorAll('.designer')) f.hidden = !atLeast('designer');
  for (const f of document.querySelectorAll('.reviewer')) f.hidden = !atLeast('reviewer');
  await Promise.all([listComponents(), listJobs(), listTopics()]);
  listen();
}

// ------------------------------------------------------------------ components and checks
async function listComponents() {
  const components = await api('GET', projectPath('/components'));
  $('components').replaceChildren(el('tr', {}, ['component', 'versions', 'latest file'].map((h) => el('th', { text: h }))),
    ...components.map((c) => el('tr', {}, [el('td', { text: c.name }), el('td', { text: String(c.versions.length) }),
      el('td', { text: `${c.versions.at(-1).filename} (${c.versions.at(-1).size.toLocaleString('en-US')} bytes)` })])));
}
$('upload').addEventListener('submit', async (e) => {
  e.preventDefault();
  const file = $('component-file').files[0];
  try {
    await api('POST', projectPath(`/components/${encodeURIComponent($('component-name').value)}/versions?file=${encodeURIComponent(file.name)}`),
      await file.arrayBuffer(), 'application/octet-stream');
    show(null);
    await listComponents();
  } catch (err) { show(err); }
});
$('new-check').addEventListener('submit', async (e) => {
  e.preventDefault();
  const translate = $('check-translate').value.split(',').map(Number);
  try {
    await api('POST', projectPath('/jobs'), { kind: 'interference', a: $('check-a').value, b: $('check-b').value, translate });
    show(null);
  } catch (err) { show(err); }
});
async function listJobs() {
  state.jobs = await api('GET', projectPath('/jobs'));
  $('jobs').replaceChildren(el('tr', {}, ['check', 'components', 'state', 'pairs', 'new / still / resolved'].map((h) => el('th', { text: h }))),
    ...state.jobs.slice().reverse().map((j) => {
      const r = j.result || {}, f = r.findings || {};
      return el('tr', { 'data-key': `job-${j.id}`, class: state.job === j.id ? 'selected' : '', on: { click: () => openJob(j.id) } }, [
        el('td', { text: `#${j.id}` }), el('td', { text: `${j.inputs.components.join(" \u00d7 ")}` }),
        el('td', { text: j.state + (j.message ? `: ${j.message}` : ''), class: `state-${j.state}` }),
        el('td', { text: r.pair_count === undefined ? '' : String(r.pair_count) }),
        el('td', { text: r.findings ? `${f.new} / ${f.persistent} / ${f.resolved}` : '' })]);
    }));
}
async function openJob(id) {
  const job = await api('GET', projectPath(`/jobs/${id}`));
  state.job = id;
  $('check-view').hidden = false;
  $('check-title').textContent = `Check #${id}: ${job.state}` + (job.result ? `, ${job.result.pair_count} intersecting triangle pairs` : '');
  const head = el('tr', {}, ['finding', 'state', 'solid.face A', 'solid.face B', 'pairs', ''].map((h) => el('th', { text: h })));
  $('findings').replaceChildren(head, ...job.findings.map((f, i) => {
    const g = f.payload;
    const make = el('button', { type: 'button', text: 'Create item', class: 'reviewer' });
    make.hidden = !atLeast('reviewer') || f.state === 'resolved';
    make.addEventListener('click', (e) => { e.stopPropagation(); createItem(job, f, i); });
    return el('tr', { 'data-key': f.key, on: { click: () => frame().showGroup?.(groupIndex(job, f)) } }, [
      el('td', { text: f.key.slice(0, 8) }), el('td', { text: f.state, class: `finding-${f.state}` }),
      el('td', { text: `${g.solid_a}.${g.face_a}` }), el('td', { text: `${g.solid_b}.${g.face_b}` }),
      el('td', { text: String(g.pairs) }), el('td', {}, [make])]);
  }));
  await loadPage(id, job.state === 'succeeded');
  listJobs();
}
const groupIndex = (job, f) => job.findings.filter((x) => x.state !== 'resolved').indexOf(f);
const frame = () => ($('check-page').contentWindow && $('check-page').contentWindow.mtcsInterference) || {};
function loadPage(id, ready) {
  return new Promise((resolve) => {
    const page = $('check-page');
    if (!ready) { page.removeAttribute('src'); resolve(); return; }
    const src = projectPath(`/jobs/${id}/page`);
    if (page.getAttribute('src') === src && frame().viewpoint) { resolve(); return; }
    page.onload = () => resolve();
    page.setAttribute('src', src);
  });
}
async function createItem(job, f) {
  const g = f.payload;
  const title = `${g.component_a} ${g.solid_a}.${g.face_a} \u00d7 ${g.component_b} ${g.solid_b}.${g.face_b}: ${g.pairs} pairs`;
  frame().showGroup?.(groupIndex(job, f));
  const viewpoint = frame().viewpoint ? { ...frame().viewpoint(), job: job.id } : null;
  try {
    const t = await api('POST', projectPath('/topics'), { title, finding: f.key, comment: `found by check #${job.id}`, viewpoint });
    await listTopics();
    openTopic(t.id);
  } catch (err) { show(err); }
}

// ------------------------------------------------------------------ review items
async function listTopics() {
  state.topics = await api('GET', projectPath('/topics'));
  $('topics').replaceChildren(el('tr', {}, ['item', 'title', 'status', 'comments'].map((h) => el('th', { text: h }))),
    ...state.topics.map((t) => el('tr', { 'data-key': `topic-${t.id}`, class: state.topic === t.id ? 'selected' : '', on: { click: () => openTopic(t.id) } }, [
      el('td', { text: `#${t.id}` }), el('td', { text: t.title }), el('td', { text: t.status }), el('td', { text: String(t.comments.length) })])));
  if (state.topic) renderTopic(state.topics.find((t) => t.id === state.topic));
}
function openTopic(id) {
  state.topic = id;
  listTopics();
}
function renderTopic(t) {
  if (!t) return;
  $('topic').hidden = false;
  $('topic-title').textContent = `#${t.id} ${t.title}`;
  const select = $('topic-status');
  select.replaceChildren(...t.authorization.topic_status.map((s) => el('option', { value: s, text: s })));
  select.value = t.status;
  select.disabled = !t.authorization.topic_actions.includes('updateStatus');
  $('comments').replaceChildren(...t.comments.map((c) => {
    const li = el('li', {}, [el('span', { class: 'who', text: `${c.author}: ` }), c.text]);
    if (c.viewpoint) li.append(' ', el('button', { type: 'button', text: 'Open view', on: { click: () => openViewpoint(c.viewpoint) } }));
    return li;
  }));
}
async function openViewpoint(v) {
  if (v.job && v.job !== state.job) await openJob(v.job);
  frame().setViewpoint?.(v);
}
$('topic-status').addEventListener('change', async () => {
  try { await api('PATCH', projectPath(`/topics/${state.topic}`), { status: $('topic-status').value }); await listTopics(); } catch (err) { show(err); }
});
$('new-comment').addEventListener('submit', async (e) => {
  e.preventDefault();
  const viewpoint = $('comment-view').checked && frame().viewpoint ? { ...frame().viewpoint(), job: state.job } : null;
  try {
    await api('POST', projectPath(`/topics/${state.topic}/comments`), { text: $('comment-text').value, viewpoint });
    $('comment-text').value = '';
    await listTopics();
  } catch (err) { show(err); }
});

// ------------------------------------------------------------------ live
function listen() {
  if (state.events) state.events.close();
  // EventSource resends Last-Event-ID when it reconnects: the server replays what was missed.
  state.events = new EventSource(projectPath(`/events?after=${state.lastEvent}`));
  const refresh = { 'version.created': listComponents, 'job.queued': listJobs, 'job.started': listJobs, 'job.finished': listJobs,
    'topic.created': listTopics, 'topic.updated': listTopics, 'comment.created': listTopics, 'member.updated': () => {} };
  for (const [type, f] of Object.entries(refresh))
    state.events.addEventListener(type, (e) => {
      state.lastEvent = Math.max(state.lastEvent, Number(e.lastEventId));
      const data = JSON.parse(e.data);
      $('activity').prepend(el('li', { text: `${type} ${data.title || data.text || data.component || (data.job ? `#${data.job} ${data.state || ''}` : '')}` }));
      f();
      if (type === 'job.finished' && state.job === data.job) openJob(data.job);
    });
}

window.mtcsReview = { state, openJob, openTopic, openViewpoint, frame, topics: () => state.topics, jobs: () => state.jobs };
start();
