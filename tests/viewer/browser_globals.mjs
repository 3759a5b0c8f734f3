// The few browser globals three.js's GLTFLoader touches when it parses a .glb under Node: `self`, and
// `document.createElementNS` for embedded textures, answered by an image that loads at once and holds
// no pixels (nothing is drawn under Node).
globalThis.self = globalThis;
class NoPixelsImage {
  constructor() { this.listeners = {}; }
  addEventListener(type, f) { (this.listeners[type] ??= []).push(f); }
  removeEventListener() {}
  set src(_) { setTimeout(() => (this.listeners.load || []).forEach(f => f.call(this, {})), 0); }
}
globalThis.document = { createElementNS: () => new NoPixelsImage() };
