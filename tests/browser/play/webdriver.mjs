// A headless Chromium driven through Debian's chromedriver (WebDriver over HTTP, with node's own
// fetch): pages opened, scripts run, real key events (WebDriver actions, which chromedriver
// sends as the DevTools Protocol's Input.dispatchKeyEvent, so the page sees trusted keydown and
// keyup events), clicks, screenshots and downloads. Used by the play page's test and benchmark.
import { spawn } from "node:child_process";
import fs from "node:fs";
import net from "node:net";
import path from "node:path";

function freePort() {
  return new Promise((resolve, reject) => {
    const server = net.createServer();
    server.on("error", reject);
    server.listen(0, "127.0.0.1", () => {
      const { port } = server.address();
      server.close(() => resolve(port));
    });
  });
}

// The first of `names` found on the PATH (Debian's chromium and chromium-driver put theirs there).
export function findProgram(...names) {
  for (const name of names)
    for (const dir of (process.env.PATH || "").split(path.delimiter)) {
      const candidate = path.join(dir, name);
      try {
        fs.accessSync(candidate, fs.constants.X_OK);
        return candidate;
      } catch (e) { /* not here */ }
    }
  throw new Error(`none of ${names.join(", ")} is installed: scripts/setup-browser.sh driver installs them`);
}

export function sleep(ms) { return new Promise((resolve) => setTimeout(resolve, ms)); }

// The WebDriver names of the keys the tests press (the W3C spec's code points for named keys).
export const KEYS = { space: " ", delete: "\uE017", q: "q", w: "w" };

export class Browser {
  // Starts chromedriver and a headless chromium whose downloads land in downloadDir.
  static async start({ profileDir, downloadDir }) {
    const chromium = findProgram("chromium", "chromium-browser"), chromedriver = findProgram("chromedriver");
    const port = await freePort();
    const driver = spawn(chromedriver, [`--port=${port}`], { stdio: ["ignore", "ignore", "pipe"] });
    const browser = new Browser(port, driver);
    for (let i = 0; ; i++) {
      try {
        const status = await (await fetch(`http://127.0.0.1:${port}/status`)).json();
        if (status.value && status.value.ready) break;
      } catch (e) { /* not listening yet */ }
      if (i > 100) throw new Error("chromedriver did not start");
      await sleep(100);
    }
    const session = await browser.request("POST", "/session", {
      capabilities: { alwaysMatch: { browserName: "chrome", "goog:chromeOptions": {
        binary: chromium,
        args: ["--headless=new", "--no-sandbox", "--disable-gpu", "--window-size=1280,900", `--user-data-dir=${profileDir}`],
        prefs: { "download.default_directory": downloadDir, "download.prompt_for_download": false },
      } } },
    });
    browser.session = session.sessionId;
    return browser;
  }

  constructor(port, driver) {
    this.port = port;
    this.driver = driver;
    this.session = null;
  }

  async request(method, path, body) {
    const response = await fetch(`http://127.0.0.1:${this.port}${path}`, {
      method, headers: { "Content-Type": "application/json" }, body: body === undefined ? undefined : JSON.stringify(body),
    });
    const reply = await response.json();
    if (!response.ok) throw new Error(`WebDriver ${method} ${path}: ${JSON.stringify(reply.value).slice(0, 600)}`);
    return reply.value;
  }
  command(method, path, body) { return this.request(method, `/session/${this.session}${path}`, body); }

  open(url) { return this.command("POST", "/url", { url }); }
  // Runs `script` (a function body) in the page and returns its value.
  run(script, ...args) { return this.command("POST", "/execute/sync", { script, args }); }
  async waitFor(script, timeoutMs, what) {
    const until = Date.now() + timeoutMs;
    for (;;) {
      const value = await this.run(script);
      if (value) return value;
      if (Date.now() > until) throw new Error(`timed out waiting for ${what}`);
      await sleep(50);
    }
  }
  // One key pressed (down) or released (up) on the keyboard.
  key(direction, key) {
    return this.command("POST", "/actions", {
      actions: [{ type: "key", id: "keyboard", actions: [{ type: direction === "down" ? "keyDown" : "keyUp", value: key }] }],
    });
  }
  async click(selector) {
    return this.command("POST", `/element/${await this.element(selector)}/click`, {});
  }
  async element(selector) {
    const element = await this.command("POST", "/element", { using: "css selector", value: selector });
    return Object.values(element)[0];
  }
  // Chooses a file in an <input type="file">, as a person picking it in the file dialog would.
  async chooseFile(selector, file) {
    const id = await this.element(selector);
    return this.command("POST", `/element/${id}/value`, { text: file });
  }
  // Where on the page (viewport pixels) a fraction across the element's width is, halfway down.
  async pointAcross(selector, fraction) {
    const rect = await this.command("GET", `/element/${await this.element(selector)}/rect`);
    return { x: Math.round(rect.x + fraction * rect.width), y: Math.round(rect.y + rect.height / 2) };
  }
  // A mouse press and release at a fraction of the element's width (0 its left edge, 1 its right),
  // halfway down: a click on a timeline.
  async clickAcross(selector, fraction) {
    const { x, y } = await this.pointAcross(selector, fraction);
    return this.command("POST", "/actions", {
      actions: [{ type: "pointer", id: "mouse", parameters: { pointerType: "mouse" }, actions: [
        { type: "pointerMove", duration: 0, origin: "viewport", x, y },
        { type: "pointerDown", button: 0 }, { type: "pointerUp", button: 0 }] }],
    });
  }
  // A finger put on the element's centre, held for holdMs and lifted: the browser sends touch
  // and pointer events (pointerType "touch"), marked trusted. (One action sequence: chromedriver
  // does not lift a finger put down by an earlier one.)
  async touch(selector, holdMs) {
    const { x, y } = await this.pointAcross(selector, 0.5);
    return this.command("POST", "/actions", {
      actions: [{ type: "pointer", id: "finger", parameters: { pointerType: "touch" }, actions: [
        { type: "pointerMove", duration: 0, origin: "viewport", x, y }, { type: "pointerDown", button: 0 },
        { type: "pause", duration: holdMs }, { type: "pointerUp", button: 0 }] }],
    });
  }
  async screenshot(file) {
    fs.writeFileSync(file, Buffer.from(await this.command("GET", "/screenshot"), "base64"));
  }
  async quit() {
    try {
      if (this.session) await this.command("DELETE", "");
    } finally {
      this.driver.kill();
    }
  }
}
