// The world's scenery as both views draw it: the floor (its colour, its image stretched over the arena, its
// painted regions, later over earlier), and where each object stands now (a box's corners as the simulator
// computes them: counter-clockwise from the one behind and right of its centre).

// the floor's image, decoded once a snapshot (null for none); calls back when it can be drawn
export function floorPicture(floor, onLoad) {
  if (!floor || !floor.image) return null;
  const img = new Image();
  img.onload = onLoad;
  img.src = floor.image;
  return img;
}

// paints floor onto 2D context g, world mm to px by toX, toY (y up) and scale (px per mm), and over it paint (the
// regions the world's loop functions painted, an update's; absent: none)
export function paintFloor(g, floor, arena, picture, toX, toY, scale, paint) {
  g.fillStyle = floor.colour;
  g.fillRect(toX(arena.minX), toY(arena.maxY), (arena.maxX - arena.minX) * scale, (arena.maxY - arena.minY) * scale);
  if (picture && picture.complete && picture.naturalWidth > 0) {
    g.imageSmoothingEnabled = false;
    g.drawImage(picture, toX(arena.minX), toY(arena.maxY), (arena.maxX - arena.minX) * scale,
      (arena.maxY - arena.minY) * scale);
  }
  for (const r of paint ? floor.regions.concat(paint) : floor.regions) {
    g.fillStyle = r.colour;
    g.beginPath();
    if (r.kind === 'rectangle') g.rect(toX(r.x), toY(r.y + r.height), r.width * scale, r.height * scale);
    else if (r.kind === 'disc') g.arc(toX(r.x), toY(r.y), r.radius * scale, 0, 2 * Math.PI);
    else for (let k = 0; k < r.xy.length; k += 2) g.lineTo(toX(r.xy[k]), toY(r.xy[k + 1]));
    g.closePath(); g.fill();
  }
}

// object i's pose now: from the newest update that has the objects', else where the world put it
export function objectPose(world, poses, i) {
  const o = world.objects[i], p = poses && poses.objects;
  return p ? [p.x[i], p.y[i], p.heading[i]] : [o.x, o.y, o.heading];
}

// whether object i is out of the world (the newest update says the loop functions took it out)
export function objectGone(poses, i) {
  const p = poses && poses.objects;
  return !!(p && p.gone && p.gone.includes(i));
}

// a box's corners at (x, y), heading deg: x0, y0, ... x3, y3 (mm)
export function corners(o, x, y, heading) {
  const h = heading * Math.PI / 180, c = Math.cos(h), s = Math.sin(h), hw = o.width / 2, hd = o.depth / 2;
  const out = [];
  for (let k = 0; k < 4; k++) {
    const u = k === 0 || k === 3 ? -hw : hw, v = k < 2 ? -hd : hd;
    out.push(x + u * c - v * s, y + u * s + v * c);
  }
  return out;
}
