"""Inline script of the HTML report (:mod:`juncture.plots.report`): a small wireframe viewer.

The viewer reads the JSON of ``<script type="application/json" id="jr-data">`` (written
by :func:`juncture.plots.report.wireframe_data`) and draws every polyline on ``<canvas
id="jr-canvas">`` in orthographic projection, intersections in the data's
``intersection_colour``. Axes are the project's (x aft, y starboard, z up). Drag rotates
(yaw about z, pitch about the screen's horizontal axis), shift-drag pans, the wheel zooms,
the buttons select a view (fitted to the canvas) or reset. It draws once as soon as it
runs, and again on every change or resize.
"""

from __future__ import annotations

__all__ = ["REPORT_JS"]

#: The viewer, embedded in a ``<script>`` element at the end of the body (plain ES5).
REPORT_JS = r"""
(function () {
  "use strict";
  var data = JSON.parse(document.getElementById("jr-data").textContent);
  var canvas = document.getElementById("jr-canvas");
  var ctx = canvas.getContext("2d");
  var VIEWS = {iso: [0.75, 0.5], top: [0, Math.PI / 2], side: [0, 0],
               front: [Math.PI / 2, 0]};
  var state = {yaw: VIEWS.iso[0], pitch: VIEWS.iso[1], zoom: 1, panX: 0, panY: 0,
               extX: 1, extU: 1};
  var c = data.centre, size = data.size || 1;

  function eachPoint(fn) {
    data.networks.concat(data.intersections).forEach(function (item) {
      item.lines.forEach(function (line) {
        for (var k = 0; k < line.length; k += 3) {
          fn(line[k] - c[0], line[k + 1] - c[1], line[k + 2] - c[2]);
        }
      });
    });
  }

  function fit() {  // the model's projected extent in this view, kept while rotating
    var b = basis(), ex = 1e-9 * size, eu = 1e-9 * size;
    eachPoint(function (px, py, pz) {
      ex = Math.max(ex, Math.abs(b.X[0] * px + b.X[1] * py + b.X[2] * pz));
      eu = Math.max(eu, Math.abs(b.U[0] * px + b.U[1] * py + b.U[2] * pz));
    });
    state.extX = 2 * ex;
    state.extU = 2 * eu;
  }

  function basis() {
    var cy = Math.cos(state.yaw), sy = Math.sin(state.yaw);
    var cp = Math.cos(state.pitch), sp = Math.sin(state.pitch);
    // screen right X, screen up U, toward the viewer D: a right-handed set (X x U = D).
    return {X: [cy, -sy, 0], U: [sy * sp, cy * sp, cp], D: [-sy * cp, -cy * cp, sp]};
  }

  function draw() {
    var dpr = window.devicePixelRatio || 1;
    var w = canvas.clientWidth, h = canvas.clientHeight;
    if (canvas.width !== Math.round(w * dpr) || canvas.height !== Math.round(h * dpr)) {
      canvas.width = Math.round(w * dpr);
      canvas.height = Math.round(h * dpr);
    }
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    ctx.fillStyle = "#fbfbfd";
    ctx.fillRect(0, 0, w, h);
    var b = basis();
    var s = state.zoom * 0.9 * Math.min(w / state.extX, h / state.extU);
    var ox = w / 2 + state.panX, oy = h / 2 + state.panY;
    function path(line) {
      for (var k = 0; k < line.length; k += 3) {
        var px = line[k] - c[0], py = line[k + 1] - c[1], pz = line[k + 2] - c[2];
        var sx = ox + s * (b.X[0] * px + b.X[1] * py + b.X[2] * pz);
        var sy = oy - s * (b.U[0] * px + b.U[1] * py + b.U[2] * pz);
        if (k === 0) { ctx.moveTo(sx, sy); } else { ctx.lineTo(sx, sy); }
      }
    }
    ctx.lineJoin = "round";
    data.networks.forEach(function (net) {
      ctx.beginPath();
      net.lines.forEach(path);
      ctx.strokeStyle = data.components[net.component].colour;
      ctx.globalAlpha = net.image ? 0.45 : 0.9;
      ctx.lineWidth = 0.8;
      ctx.stroke();
    });
    ctx.globalAlpha = 1;
    ctx.lineWidth = 1.8;
    ctx.strokeStyle = data.intersection_colour || "#d62728";
    data.intersections.forEach(function (inter) {
      ctx.beginPath();
      inter.lines.forEach(path);
      ctx.stroke();
    });
    axes(b, h);
  }

  function axes(b, h) {
    var names = ["x", "y", "z"], cols = ["#c0392b", "#27ae60", "#2c6fbb"];
    var x0 = 42, y0 = h - 42, L = 28;
    ctx.lineWidth = 2;
    ctx.font = "12px sans-serif";
    for (var i = 0; i < 3; i++) {
      var ex = L * b.X[i], ey = -L * b.U[i];
      ctx.strokeStyle = cols[i];
      ctx.fillStyle = cols[i];
      ctx.beginPath();
      ctx.moveTo(x0, y0);
      ctx.lineTo(x0 + ex, y0 + ey);
      ctx.stroke();
      ctx.fillText(names[i], x0 + 1.2 * ex - 3, y0 + 1.2 * ey + 4);
    }
  }

  function setView(name) {
    state.yaw = VIEWS[name][0];
    state.pitch = VIEWS[name][1];
    state.zoom = 1;
    state.panX = 0;
    state.panY = 0;
    fit();
    draw();
  }

  var drag = null;
  canvas.addEventListener("pointerdown", function (e) {
    drag = {x: e.clientX, y: e.clientY, pan: e.shiftKey || e.button === 2};
    canvas.setPointerCapture(e.pointerId);
    canvas.style.cursor = "grabbing";
  });
  canvas.addEventListener("pointermove", function (e) {
    if (!drag) { return; }
    var dx = e.clientX - drag.x, dy = e.clientY - drag.y;
    drag.x = e.clientX;
    drag.y = e.clientY;
    if (drag.pan) {
      state.panX += dx;
      state.panY += dy;
    } else {
      state.yaw += dx * 0.01;
      state.pitch = Math.max(-Math.PI / 2, Math.min(Math.PI / 2, state.pitch + dy * 0.01));
    }
    draw();
  });
  function release() { drag = null; canvas.style.cursor = "grab"; }
  canvas.addEventListener("pointerup", release);
  canvas.addEventListener("pointercancel", release);
  canvas.addEventListener("contextmenu", function (e) { e.preventDefault(); });
  canvas.addEventListener("wheel", function (e) {
    e.preventDefault();
    state.zoom = Math.max(0.05, Math.min(80, state.zoom * Math.exp(-e.deltaY * 0.0015)));
    draw();
  }, {passive: false});
  Array.prototype.forEach.call(document.querySelectorAll("[data-view]"), function (btn) {
    btn.addEventListener("click", function () { setView(btn.getAttribute("data-view")); });
  });
  window.addEventListener("resize", draw);
  fit();
  draw();
})();
"""
