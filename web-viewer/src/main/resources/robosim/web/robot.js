// The robot panel (the robot-specific viewer in the page): one robot as it senses the world - a polar
// plot in its own frame (heading up, a ring every metre, or every few when it reaches far) of its sonar cones out to each range and its
// readings its sensor shows as ranges (a laser's; each reading's display comes from the sensors' registry, WebJson:
// drawn one degree a beam, centred on the heading), its pose, command, contact, tag and only the sensors it has:
// sonar when its type has any, a reading shown by sides (bump: front, left, back, right), heat and other readings
// when its view holds them; and a log of the messages it sent and got and
// its notices. Network text is only ever set as textContent.
const LOG_LINES = 200;
const MAX_REACH = 100000; // mm

export class RobotPanel {
  constructor(root, onWatch) {
    this.root = root;
    this.select = root.querySelector('#watch');
    this.canvas = root.querySelector('#polar');
    this.facts = root.querySelector('#facts');
    this.bumpRow = root.querySelector('#bump');
    this.bumps = [...this.bumpRow.querySelectorAll('span')];
    this.log = root.querySelector('#log');
    this.robots = [];
    this.name = '';
    this.view = null;
    this.pose = null;
    this.lines = []; // (log lines not yet shown: added to the page once a frame, not one by one)
    this.select.onchange = () => onWatch(this.select.value);
  }

  // a new world: its robots to choose from; the robot watched stays chosen if it is in it. A view of a later
  // step than the world's is of another time (the run before, or the steps a replay's seek went back from);
  // one of the world's step may have come first (views come on a connection of their own)
  world(snapshot) {
    this.robots = snapshot.robots;
    const keep = this.name;
    this.select.replaceChildren(new Option('(none)', ''), ...snapshot.robots.map((r) => new Option(r.name, r.name)));
    this.select.value = this.robots.some((r) => r.name === keep) ? keep : '';
    if (this.view && this.view.step > snapshot.step) this.view = null;
  }

  // the page now watches this robot ('' for none)
  watching(name) {
    if (name !== this.name) { this.view = null; this.lines = []; this.log.replaceChildren(); }
    this.name = name;
    this.select.value = name;
    this.root.classList.toggle('idle', name === '');
  }

  poses(update) {
    const i = this.robots.findIndex((r) => r.name === this.name);
    this.pose = i < 0 ? null : { i, x: update.x[i], y: update.y[i], heading: update.heading[i],
      sonar: update.sonar[i] || [], step: update.step, gone: update.departed.includes(this.name),
      held: (update.held || []).includes(this.name) };
  }

  show(v) {
    if (v.name !== this.name) return;
    this.view = v;
    // steps as every display numbers them: steps completed, the wire's step + 1 (protocol/README.md, "Step numbers")
    const at = v.since === v.step ? `step ${v.step + 1}` : `steps ${v.since + 1}-${v.step + 1}`;
    if (v.leftOut > 0) this.line(`${at}: ${v.leftOut} earlier messages and notices left out`);
    for (const m of v.sent) this.line(`${at}  out  to ${m.to}: ${m.text}`);
    for (const m of v.delivered) this.line(`${at}  in   from ${m.from}: ${m.text}`);
    for (const n of v.notices) this.line(`${at}  notice: ${n}`);
  }

  ended(reason) {
    this.watching('');
    this.line(`-- ${reason}`);
  }

  line(text) {
    this.lines.push(text);
    if (this.lines.length > LOG_LINES) this.lines.splice(0, this.lines.length - LOG_LINES);
  }

  // the lines that came since the last frame, at once: one layout a frame however many messages came
  showLines() {
    if (this.lines.length === 0) return;
    const add = document.createDocumentFragment();
    for (const text of this.lines) { const li = document.createElement('li'); li.textContent = text; add.append(li); }
    this.lines = [];
    this.log.append(add);
    while (this.log.childElementCount > LOG_LINES) this.log.firstChild.remove();
    this.log.scrollTop = this.log.scrollHeight;
  }

  draw() {
    this.showLines();
    if (!this.name) return;
    const r = this.robots.find((x) => x.name === this.name);
    const v = this.view, p = this.pose;
    const lines = [`${this.name} (${r ? r.type : '?'})`];
    if (p) lines.push(p.gone ? 'it has left the simulation'
      : p.held ? `held since it was lost: standing at x ${(p.x / 1000).toFixed(3)} y ${(p.y / 1000).toFixed(3)} m`
      : `step ${p.step + 1}  x ${(p.x / 1000).toFixed(3)} y ${(p.y / 1000).toFixed(3)} m  ${p.heading.toFixed(1)} deg`);
    let bump = null;
    if (v) {
      const sonar = r && r.sonars.length > 0 ? `sonar ${v.sonar ? 'asked' : 'not asked'}, ` : '';
      lines.push(`command (step ${v.step + 1}): move ${v.move.toFixed(1)} mm, turn ${v.turn.toFixed(1)} deg`,
        `  ${sonar}tag ${v.tag ? 'asked' : 'no'}`,
        `contact ${v.contact || 'none'}   tagged ${v.tagged || 'none'}`);
      for (const s of v.readings) {
        if (s.display === 'SIDES') { bump = s.values; this.bumps.forEach((b, k) => { b.textContent = s.sides[k]; }); }
        lines.push(`${s.name}  ${s.values.length <= 6 ? s.values.join(' ')
          : `${s.values.length} values, ${Math.min(...s.values)} to ${Math.max(...s.values)}`}`);
      }
    } else lines.push('(waiting for its first step)');
    this.facts.textContent = lines.join('\n');
    this.bumpRow.classList.toggle('hidden', !bump);
    this.bumps.forEach((b, k) => b.classList.toggle('hit', !!bump && bump[k] !== 0));
    this.polar(r, v, p);
  }

  polar(r, v, p) {
    const c = this.canvas, g = c.getContext('2d'), size = c.width, mid = size / 2;
    g.fillStyle = '#f7f8fa'; g.fillRect(0, 0, size, size);
    if (!r) return;
    const lasers = v ? v.readings.filter((s) => s.display === 'RANGES').map((s) => s.values) : [];
    let reach = 1000; // mm: the farthest a sonar or laser reaches, at most MAX_REACH (network values)
    const seen = (d) => { if (Number.isFinite(d)) reach = Math.min(MAX_REACH, Math.max(reach, d)); };
    for (const s of r.sonars) seen(s.range + Math.hypot(s.x, s.y));
    for (const l of lasers) l.forEach(seen);
    const k = (mid - 8) / reach; // px per mm; robot frame: x forward = up, y left = left
    const ring = 1000 * Math.ceil(reach / 10000); // (at most ten rings)
    g.strokeStyle = '#d5d9e0'; g.lineWidth = 1;
    for (let m = ring; m <= reach; m += ring) { g.beginPath(); g.arc(mid, mid, m * k, 0, 2 * Math.PI); g.stroke(); }
    if (p && !p.gone) {
      g.fillStyle = 'rgba(31,119,180,0.3)';
      r.sonars.forEach((s, j) => {
        if (!(p.sonar[j] >= 0)) return; // (none read, or not a range)
        const range = Math.min(p.sonar[j], reach);
        const ox = mid - s.y * k, oy = mid - s.x * k, a = -Math.PI / 2 - s.angle * Math.PI / 180;
        const half = s.cone * Math.PI / 360;
        g.beginPath(); g.moveTo(ox, oy); g.arc(ox, oy, range * k, a - half, a + half); g.closePath(); g.fill();
      });
    }
    g.fillStyle = '#d62728';
    for (const l of lasers) {
      const first = -(l.length - 1) / 2;
      l.forEach((d, b) => {
        if (!Number.isFinite(d) || d > reach) return;
        const a = (first + b) * Math.PI / 180;
        g.fillRect(mid - Math.sin(a) * d * k - 1, mid - Math.cos(a) * d * k - 1, 2, 2);
      });
    }
    const rad = Math.max(3, r.radius * k);
    g.fillStyle = '#2a62c9'; g.beginPath(); g.arc(mid, mid, rad, 0, 2 * Math.PI); g.fill();
    g.strokeStyle = '#000'; g.beginPath(); g.moveTo(mid, mid); g.lineTo(mid, mid - rad); g.stroke();
  }
}
