// The box rain in Rapier (its official WebAssembly port, @dimforge/rapier3d-compat,
// pinned in bench/package.json), for rbw_bench_rain (bench_rain.cpp), which writes the
// initial poses and reads what this prints; the outcome is computed there, the same way
// for every engine.
//
//   node bench/rapier_rain.mjs POSES STEPS H
//
// POSES: one box a line, "x y z qw qx qy qz" (unit boxes, 1 kg). The scene: gravity
// (0, -9.81, 0), time step H, Rapier's defaults otherwise (its solver iterations,
// sleeping on), friction 0.5 and restitution 0 on every collider (Rapier averages a
// pair's coefficients: 0.5), density 1 (a unit box weighs 1 kg), the ground a fixed
// cuboid 200 m x 1 m x 200 m whose top face is y = 0 (this port has no half-space
// collider builder).
//
// Prints "ms_per_step T" (wall time of the STEPS steps / STEPS, measured here around
// world.step() only), then "at STEP" and one line per box "x y z qw qx qy qz vx vy vz
// wx wy wz asleep" after the step one second before the end and after the last step.
// Exit 3 with a message on stderr when the package is not installed (npm ci in bench/).
import { readFileSync } from "node:fs";
import { performance } from "node:perf_hooks";

let RAPIER;
try {
    RAPIER = (await import("@dimforge/rapier3d-compat")).default;
} catch (e) {
    process.stderr.write("rapier_rain: @dimforge/rapier3d-compat is not installed (run npm ci in bench/)\n");
    process.exit(3);
}
await RAPIER.init();

const [posesFile, stepsText, hText] = process.argv.slice(2);
const steps = Number(stepsText);
const h = Number(hText);
const poses = readFileSync(posesFile, "utf8").trim().split("\n").map((line) => line.trim().split(/\s+/).map(Number));

const world = new RAPIER.World({ x: 0.0, y: -9.81, z: 0.0 });
world.timestep = h;

const groundBody = world.createRigidBody(RAPIER.RigidBodyDesc.fixed().setTranslation(0.0, -0.5, 0.0));
world.createCollider(RAPIER.ColliderDesc.cuboid(100.0, 0.5, 100.0).setFriction(0.5).setRestitution(0.0), groundBody);

const bodies = poses.map(([x, y, z, qw, qx, qy, qz]) => {
    const body = world.createRigidBody(
        RAPIER.RigidBodyDesc.dynamic().setTranslation(x, y, z).setRotation({ x: qx, y: qy, z: qz, w: qw }));
    world.createCollider(
        RAPIER.ColliderDesc.cuboid(0.5, 0.5, 0.5).setDensity(1.0).setFriction(0.5).setRestitution(0.0), body);
    return body;
});

function snapshot(step) {
    const lines = [`at ${step}`];
    for (const b of bodies) {
        const t = b.translation();
        const r = b.rotation();
        const v = b.linvel();
        const w = b.angvel();
        lines.push([t.x, t.y, t.z, r.w, r.x, r.y, r.z, v.x, v.y, v.z, w.x, w.y, w.z, b.isSleeping() ? 1 : 0].join(" "));
    }
    return lines.join("\n");
}

const lastSecond = steps - Math.round(1.0 / h);
let seconds = 0.0;
let before = "";
for (let k = 1; k <= steps; ++k) {
    const start = performance.now();
    world.step();
    seconds += (performance.now() - start) / 1000.0;
    if (k === lastSecond) before = snapshot(k);
}
process.stdout.write(`ms_per_step ${(1000.0 * seconds) / steps}\n${before}\n${snapshot(steps)}\n`);
