// The physics benchmark's peer: the real d3-force on floatpage's scenes.
//
// Reads {page_w, page_h, gutter, ticks, items: [[x, y, w, h], ...]} (mm) on stdin and prints
// {positions, seconds}. The simulation is d3-force's own: forceManyBody and forceX/forceY to
// the page centre at their defaults, plus a rectangle collide force (d3 ships only circles)
// written the way d3's forceCollide is, over a d3-quadtree, keeping half the gutter around
// each rectangle. After every tick, positions are clamped so each rectangle stays on the page,
// inside the print-safe margin floatpage keeps (`margin`, mm; 0 if not given).
import { forceManyBody, forceSimulation, forceX, forceY } from "d3-force";
import { quadtree } from "d3-quadtree";

function rectangleCollide(padding) {
  let nodes;
  let largest = 0;
  function force() {
    const tree = quadtree(nodes, (d) => d.x, (d) => d.y);
    for (const node of nodes) {
      const hw = node.w / 2 + padding, hh = node.h / 2 + padding;
      const reachX = hw + largest, reachY = hh + largest;
      tree.visit((quad, x0, y0, x1, y1) => {
        if (!quad.length) {
          let other = quad;
          do {
            const data = other.data;
            if (data.index > node.index) {
              const dx = node.x + node.vx - (data.x + data.vx);
              const dy = node.y + node.vy - (data.y + data.vy);
              const ox = hw + data.w / 2 + padding - Math.abs(dx);
              const oy = hh + data.h / 2 + padding - Math.abs(dy);
              if (ox > 0 && oy > 0) {
                const share = (data.w * data.h) / (node.w * node.h + data.w * data.h);
                if (ox < oy) {
                  const push = (dx === 0 ? 1 : Math.sign(dx)) * ox;
                  node.vx += push * share;
                  data.vx -= push * (1 - share);
                } else {
                  const push = (dy === 0 ? 1 : Math.sign(dy)) * oy;
                  node.vy += push * share;
                  data.vy -= push * (1 - share);
                }
              }
            }
          } while ((other = other.next));
        }
        return x0 > node.x + reachX || x1 < node.x - reachX || y0 > node.y + reachY || y1 < node.y - reachY;
      });
    }
  }
  force.initialize = (all) => {
    nodes = all;
    largest = Math.max(0, ...nodes.map((d) => Math.max(d.w, d.h) / 2 + padding));
  };
  return force;
}

const input = JSON.parse(await new Promise((resolve) => {
  let text = "";
  process.stdin.on("data", (chunk) => (text += chunk));
  process.stdin.on("end", () => resolve(text));
}));
const { page_w: pageW, page_h: pageH, gutter, ticks } = input;
const margin = input.margin ?? 0;
const nodes = input.items.map(([x, y, w, h], index) => ({ index, x, y, w, h }));
const clamp = () => {
  for (const d of nodes) {
    const hw = Math.min(d.w / 2 + margin, pageW / 2), hh = Math.min(d.h / 2 + margin, pageH / 2);
    d.x = Math.min(Math.max(d.x, hw), pageW - hw);
    d.y = Math.min(Math.max(d.y, hh), pageH - hh);
  }
};
const started = process.hrtime.bigint();
const simulation = forceSimulation(nodes)
  .force("charge", forceManyBody())
  .force("x", forceX(pageW / 2))
  .force("y", forceY(pageH / 2))
  .force("collide", rectangleCollide(gutter / 2))
  .stop();
for (let tick = 0; tick < ticks; tick++) {
  simulation.tick();
  clamp();
}
const seconds = Number(process.hrtime.bigint() - started) / 1e9;
process.stdout.write(JSON.stringify({ positions: nodes.map((d) => [d.x, d.y]), seconds }));
