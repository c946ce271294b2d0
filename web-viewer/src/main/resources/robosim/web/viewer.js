// The page's feed, the 2D view, the robot table, the status bar and the timeline. Text from the network
// is only ever set as textContent, never as markup.
import { View3D } from './view3d.js';
import { RobotPanel } from './robot.js';
import { floorPicture, paintFloor, objectPose, objectGone, corners } from './scenery.js';

const $ = (id) => document.getElementById(id);
const TRAIL = 600; // points kept per robot
let world = null, poses = null, trails = [], gone = new Set(), held = new Set(), follow = -1, picture = null;
// what the world's loop functions drew, pieced together from the 'traces' messages: [{colour, points: [x, y, ...]}]
let drawing = [], drawnPoints = 0;
let scale = 0.1, offX = 0, offY = 0, fitted = false;
let lastStep = -1, rateSteps = 0, rateSince = performance.now(), rate = 0;
let ws = null;
// draw only what changed (a page should cost the machine it runs on little): the views when there is
// something new to show, the table at most 5 times a second
let dirty = true, tableDirty = true, tableAt = 0;
const view3d = new View3D($('view3d'), TRAIL);
let watched = ''; // the robot the page watches ('' none): asked again after a reconnection
const panel = new RobotPanel($('robotPanel'), (name) => watch(name));
function watch(name) { watched = name; panel.watching(name); ask('watch ' + name); redraw(); }

function connect() {
  ws = new WebSocket(`${location.protocol === 'https:' ? 'wss' : 'ws'}://${location.host}/ws`);
  ws.onmessage = (e) => handle(JSON.parse(e.data));
  ws.onopen = () => { $('state').textContent = 'connected'; ask('status'); if (watched) ask('watch ' + watched); };
  ws.onclose = () => { $('state').textContent = 'not connected'; statusAsked = false; setTimeout(connect, 1000); };
}

let statusAsked = false; // (a status is asked for only when the last one has been answered)
function ask(request) {
  if (!ws || ws.readyState !== WebSocket.OPEN || (request === 'status' && statusAsked)) return;
  if (request === 'status') statusAsked = true;
  ws.send(request);
}

const sameArena = (a, b) => a.minX === b.minX && a.minY === b.minY && a.maxX === b.maxX && a.maxY === b.maxY;

function measureAfresh() { lastStep = -1; rateSteps = 0; rateSince = performance.now(); rate = 0; }

function handle(m) {
  switch (m.type) {
    case 'snapshot':
      // a world starts the picture afresh at its step (a new run, or a replay's seek: no trail across the
      // jump, the steps per second measured anew) but for robots that joined the running world: the
      // others keep their trails; the same arena keeps the view's zoom
      const grown = world && m.robots.length > world.robots.length
        && world.robots.every((r, i) => r.name === m.robots[i].name);
      trails = grown ? m.robots.map((r, i) => trails[i] || []) : m.robots.map(() => []);
      if (!grown) { gone = new Set(); held = new Set(); }
      measureAfresh(); // (also when robots joined: a replay sought forward across a join looks the same)
      const arenaKept = world !== null && sameArena(world.arena, m.arena);
      if (!arenaKept) fitted = false;
      world = m; poses = m.poses; drawing = []; drawnPoints = 0;
      picture = floorPicture(m.floor, () => { view3d.world(world, true); redraw(); });
      $('ended').textContent = '';
      buildTable(); view3d.world(m, arenaKept, picture); panel.world(m); dirty = tableDirty = true; wake();
      if (followName) follow = m.robots.findIndex((r) => r.name === followName);
      if (!watched && watchName && m.robots.some((r) => r.name === watchName)) watch(watchName);
      break;
    case 'update':
      poses = m; gone = new Set(m.departed); held = new Set(m.held || []);
      m.x.forEach((x, i) => { const t = trails[i]; if (t) { t.push(x, m.y[i]); if (t.length > 2 * TRAIL) t.splice(0, 2); } });
      panel.poses(m); count(m.step); showAt(m.step + 1); dirty = tableDirty = true; wake(); break;
    case 'traces': draw(m); dirty = true; wake(); break;
    case 'watchStarted': if (m.name === watched) panel.line(`-- watching ${m.name} from step ${m.step + 2}`); redraw(); break;
    case 'view': panel.show(m); redraw(); break;
    case 'viewEnded': watched = ''; panel.ended(m.reason); redraw(); break;
    case 'state': $('state').textContent = m.phase; if (m.phase === 'RUNNING') measureAfresh(); else rate = 0; redraw(); break;
    case 'end': $('state').textContent = 'ENDED'; $('ended').textContent = m.reason; rate = 0; redraw(); break;
    case 'reply': replied(m); break;
  }
}

// a piece of the drawing: a fresh one starts it afresh; what the page has of it already is skipped; one that would
// leave a gap (only a fault sends one) is left out
function draw(m) {
  if (m.fresh) { drawing = []; drawnPoints = 0; }
  if (m.firstTrace > drawing.length || m.firstPoint > drawnPoints) return;
  for (let t = drawing.length - m.firstTrace; t < m.names.length; t++) drawing.push({ colour: m.colours[t], points: [] });
  for (let k = 3 * (drawnPoints - m.firstPoint); k < m.points.length; k += 3) {
    const trace = drawing[m.points[k]];
    if (trace) trace.points.push(m.points[k + 1], m.points[k + 2]);
    drawnPoints++;
  }
}

function count(step) {
  if (lastStep >= 0 && step > lastStep) rateSteps += step - lastStep;
  lastStep = step;
  const now = performance.now();
  if (now - rateSince >= 1000) { rate = rateSteps * 1000 / (now - rateSince); rateSteps = 0; rateSince = now; }
}

function replied(m) {
  if (m.request === 'status') statusAsked = false;
  if (m.request === 'status' && m.ok) {
    const replay = m.replay === true;
    $('replay').classList.toggle('hidden', !replay);
    if (replay) lastShown = m.last_step;
    if (replay && document.activeElement !== $('timeline')) {
      $('timeline').min = m.first_step; $('timeline').max = m.last_step;
      // the step the page shows: the status's (a second old) only until the page has an update of its own
      showAt(poses ? poses.step + 1 : m.step);
      if (document.activeElement !== $('speed')) showSpeed(m.speed);
    }
    if (!poses || m.state === 'PAUSED' || m.state === 'ENDED' || m.state === 'WAITING') $('state').textContent = m.state;
  } else if (m.request === 'watch' && !m.ok) {
    watched = ''; panel.ended(m.error); $('reply').textContent = 'watch: refused: ' + m.error; redraw();
  } else if (m.request !== 'status') {
    $('reply').textContent = m.request + ': ' + (m.ok ? (m.message || 'ok') : 'refused: ' + m.error);
  }
}

// a replay's timeline and its 'step / last' follow the steps shown (a status comes once a second)
let lastShown = null;
function showAt(step) {
  if (lastShown === null || document.activeElement === $('timeline')) return;
  $('timeline').value = step; $('at').textContent = `${step} / ${lastShown}`;
}

// the replay's speed in the list, added where it is not one of the list's own (--speed 20)
function showSpeed(speed) {
  const list = $('speed'), text = String(speed);
  if (![...list.options].some((o) => o.value === text)) {
    const option = document.createElement('option');
    option.textContent = text;
    list.insertBefore(option, [...list.options].find((o) => Number(o.value) > speed) || null);
  }
  list.value = text;
}

function buildTable() {
  const body = $('robots').tBodies[0];
  body.replaceChildren();
  world.robots.forEach((r, i) => {
    const tr = body.insertRow();
    tr.dataset.robot = i;
    for (let c = 0; c < 4; c++) tr.insertCell();
    tr.cells[0].textContent = r.name;
    tr.onclick = () => { follow = follow === i ? -1 : i; };
  });
}

function showTable() {
  const rows = $('robots').tBodies[0].rows;
  for (let i = 0; i < rows.length && poses; i++) {
    const r = rows[i];
    r.cells[1].textContent = (poses.x[i] / 1000).toFixed(3);
    r.cells[2].textContent = (poses.y[i] / 1000).toFixed(3);
    r.cells[3].textContent = poses.heading[i].toFixed(1);
    r.classList.toggle('gone', gone.has(world.robots[i].name) || held.has(world.robots[i].name));
    r.classList.toggle('followed', follow === i);
  }
  const tags = $('tags');
  const list = poses ? poses.tags.slice(-10) : [];
  if (tags.childElementCount !== list.length || (list.length && tags.lastChild.textContent !== list[list.length - 1])) {
    tags.replaceChildren(...list.map((t) => { const li = document.createElement('li'); li.textContent = t; return li; }));
  }
}

// ---- the 2D view: world mm -> screen px, y up ----
const canvas = $('view2d');
const toX = (x) => x * scale + offX;
const toY = (y) => canvas.height - (y * scale + offY);

function fit() {
  const a = world.arena, w = canvas.width, h = canvas.height;
  scale = 0.95 * Math.min(w / (a.maxX - a.minX), h / (a.maxY - a.minY));
  offX = (w - (a.maxX - a.minX) * scale) / 2 - a.minX * scale;
  offY = (h - (a.maxY - a.minY) * scale) / 2 - a.minY * scale;
  fitted = true;
}

function draw2d() {
  const g = canvas.getContext('2d');
  if (canvas.width !== canvas.clientWidth || canvas.height !== canvas.clientHeight) {
    canvas.width = canvas.clientWidth; canvas.height = canvas.clientHeight; fitted = false;
  }
  g.fillStyle = '#fff'; g.fillRect(0, 0, canvas.width, canvas.height);
  if (!world || !poses) return;
  if (!fitted) fit();
  if (follow >= 0) { offX = canvas.width / 2 - poses.x[follow] * scale; offY = canvas.height / 2 - poses.y[follow] * scale; }
  const a = world.arena;
  paintFloor(g, world.floor, a, picture, toX, toY, scale, poses.paint);
  g.strokeStyle = '#444'; g.lineWidth = 2;
  g.strokeRect(toX(a.minX), toY(a.maxY), (a.maxX - a.minX) * scale, (a.maxY - a.minY) * scale);
  g.fillStyle = '#8a8a8a';
  for (const o of world.obstacles) {
    g.beginPath();
    for (let k = 0; k < o.xy.length; k += 2) g.lineTo(toX(o.xy[k]), toY(o.xy[k + 1]));
    g.closePath(); g.fill();
  }
  world.objects.forEach((o, i) => { // (in their colours; a movable one outlined dashed; none taken out of the world)
    if (objectGone(poses, i)) return;
    const [x, y, h] = objectPose(world, poses, i);
    g.beginPath();
    if (o.shape === 'cylinder') g.arc(toX(x), toY(y), o.width / 2 * scale, 0, 2 * Math.PI);
    else { const c = corners(o, x, y, h); for (let k = 0; k < 8; k += 2) g.lineTo(toX(c[k]), toY(c[k + 1])); }
    g.closePath(); g.fillStyle = o.colour; g.fill();
    g.setLineDash(o.movable ? [3, 3] : []); g.strokeStyle = '#222'; g.lineWidth = 1; g.stroke(); g.setLineDash([]);
  });
  world.lights.forEach((l, i) => { // (a disc of its colour with a glow; hollow when off, as loop functions switch it)
    const r = Math.max(4, 60 * scale);
    const on = poses.lightsOn ? poses.lightsOn[i] : l.on;
    if (on && l.intensity > 0) {
      g.fillStyle = l.colour; g.globalAlpha = 0.3;
      g.beginPath(); g.arc(toX(l.x), toY(l.y), 2 * r, 0, 2 * Math.PI); g.fill(); g.globalAlpha = 1;
      g.beginPath(); g.arc(toX(l.x), toY(l.y), r, 0, 2 * Math.PI); g.fill();
    }
    g.strokeStyle = '#222'; g.lineWidth = 1; g.beginPath(); g.arc(toX(l.x), toY(l.y), r, 0, 2 * Math.PI); g.stroke();
  });
  g.lineWidth = 2;
  for (const d of drawing) {
    g.strokeStyle = d.colour; g.beginPath();
    for (let k = 0; k < d.points.length; k += 2) g.lineTo(toX(d.points[k]), toY(d.points[k + 1]));
    g.stroke();
  }
  if ($('trails').checked) {
    g.strokeStyle = 'rgba(40,90,200,0.35)'; g.lineWidth = 1;
    for (const t of trails) {
      g.beginPath();
      for (let k = 0; k < t.length; k += 2) g.lineTo(toX(t[k]), toY(t[k + 1]));
      g.stroke();
    }
  }
  world.robots.forEach((r, i) => {
    const x = poses.x[i], y = poses.y[i], h = poses.heading[i] * Math.PI / 180;
    const out = gone.has(r.name) || held.has(r.name);
    if ($('sonar').checked && !out) {
      g.strokeStyle = 'rgba(220,60,60,0.5)';
      r.sonars.forEach((s, k) => {
        const range = (poses.sonar[i] || [])[k];
        if (range === undefined) return;
        const sx = x + s.x * Math.cos(h) - s.y * Math.sin(h), sy = y + s.x * Math.sin(h) + s.y * Math.cos(h);
        const d = h + s.angle * Math.PI / 180;
        g.beginPath(); g.moveTo(toX(sx), toY(sy));
        g.lineTo(toX(sx + range * Math.cos(d)), toY(sy + range * Math.sin(d))); g.stroke();
      });
    }
    const rad = Math.max(2, r.radius * scale);
    g.fillStyle = out ? '#ccc' : i === follow ? '#e8a200' : '#2a62c9';
    g.beginPath(); g.arc(toX(x), toY(y), rad, 0, 2 * Math.PI); g.fill();
    g.strokeStyle = '#000'; g.lineWidth = 1.5;
    g.beginPath(); g.moveTo(toX(x), toY(y)); g.lineTo(toX(x + r.radius * Math.cos(h)), toY(y + r.radius * Math.sin(h))); g.stroke();
    const lit = poses.leds ? poses.leds[i] || [] : [];
    r.leds.forEach(([lx, ly], k) => { // (each lit LED a dot of its colour where it sits on the robot)
      if (!lit[k] || lit[k] === '#000000') return;
      const px = x + lx * Math.cos(h) - ly * Math.sin(h), py = y + lx * Math.sin(h) + ly * Math.cos(h);
      g.fillStyle = lit[k]; g.beginPath(); g.arc(toX(px), toY(py), Math.max(2, 12 * scale), 0, 2 * Math.PI); g.fill();
    });
    g.fillStyle = '#222';
    g.fillText(r.name + (held.has(r.name) ? ' (held)' : out ? ' (left)' : ''), toX(x) + rad + 2, toY(y) - rad);
  });
}

canvas.addEventListener('wheel', (e) => {
  e.preventDefault();
  const f = e.deltaY < 0 ? 1.2 : 1 / 1.2, mx = e.offsetX, my = canvas.height - e.offsetY;
  offX = mx - (mx - offX) * f; offY = my - (my - offY) * f; scale *= f;
}, { passive: false });
let drag = null, moved = false;
canvas.addEventListener('mousedown', (e) => { drag = [e.clientX, e.clientY]; moved = false; });
canvas.addEventListener('click', (e) => { // a click, not a drag, on a robot: watch it
  if (moved || !world || !poses) return;
  const hit = world.robots.findIndex((r, i) => Math.hypot(toX(poses.x[i]) - e.offsetX, toY(poses.y[i]) - e.offsetY)
    <= Math.max(6, r.radius * scale));
  if (hit >= 0) watch(world.robots[hit].name);
});
window.addEventListener('mouseup', () => { drag = null; });
window.addEventListener('mousemove', (e) => {
  if (!drag) return;
  moved = true;
  offX += e.clientX - drag[0]; offY -= e.clientY - drag[1]; drag = [e.clientX, e.clientY]; follow = -1; tableDirty = true;
});
$('fit').onclick = () => { follow = -1; fitted = false; tableDirty = true; view3d.fit(); };
document.querySelectorAll('input[name=view]').forEach((r) => r.onchange = () => {
  const three = document.querySelector('input[name=view]:checked').value === '3d';
  redraw();
  canvas.classList.toggle('hidden', three); $('view3d').classList.toggle('hidden', !three);
});
$('pause').onclick = () => ask('pause');
$('resume').onclick = () => ask('resume');
$('stepOne').onclick = () => ask('step 1');
$('timeline').onchange = () => ask('seek ' + $('timeline').value);
$('speed').onchange = () => ask('speed ' + $('speed').value);

// frames only on demand: a page with nothing new asks the browser for no frame at all
let scheduled = false;
function wake() {
  if (!scheduled) { scheduled = true; requestAnimationFrame(frame); }
}
function frame(now) {
  scheduled = false;
  if (dirty) {
    dirty = false;
    $('step').textContent = poses ? poses.step + 1 : '-'; // steps completed (protocol/README.md, "Step numbers")
    $('rate').textContent = rate.toFixed(1);
    if (!canvas.classList.contains('hidden')) draw2d();
    else view3d.render(poses, gone, held, follow, $('trails').checked ? trails : null, drawing);
    panel.draw();
  }
  if (tableDirty) {
    if (now - tableAt > 200) { showTable(); tableDirty = false; tableAt = now; } else setTimeout(wake, 200 - (now - tableAt));
  }
}
const redraw = () => { dirty = true; wake(); };
['trails', 'sonar', 'fit'].forEach((id) => $(id).addEventListener('click', redraw));
$('robots').addEventListener('click', () => { dirty = tableDirty = true; wake(); });
window.addEventListener('mousemove', (e) => { if (e.buttons) redraw(); }); // (2D pan, 3D orbit)
$('views').addEventListener('wheel', redraw);
window.addEventListener('resize', redraw);
new ResizeObserver(redraw).observe($('views'));
// a link may say how to look: ?view=3d&sonar=1&trails=0&follow=NAME&watch=NAME
const wanted = new URLSearchParams(location.search);
if (wanted.get('view') === '3d') { document.querySelector('input[name=view][value="3d"]').checked = true;
  canvas.classList.add('hidden'); $('view3d').classList.remove('hidden'); }
if (wanted.get('sonar') === '1') $('sonar').checked = true;
if (wanted.get('trails') === '0') $('trails').checked = false;
const followName = wanted.get('follow'), watchName = wanted.get('watch');
setInterval(() => ask('status'), 1000);
connect();
wake();
