// A stand-in for the play module (the wasm32 cross build's gizmo-play.js), for the tests of the
// page `gizmo play` assembles: it defines the name the page calls and nothing else.
var GizmoPlayModule = function () { return Promise.reject(new Error("a stand-in: no simulator here")); };
