// t2spline report: the type-reduction selector, the alpha slider, the number
// field and the downloads. Every number, curve and file was computed by
// t2spline and stored in the data block (compressed); this script only
// unpacks it and swaps the parts in (it does no arithmetic on the method).
(function () {
  "use strict";
  var slider = document.getElementById("alpha");
  var field = document.getElementById("alpha-field");
  var out = document.getElementById("alpha-value");
  var regime = document.getElementById("regime");
  var note = document.getElementById("alpha-note");
  var controls = document.getElementById("controls");
  var select = document.getElementById("reduction");
  var buttons = document.querySelectorAll("button[data-stop]");
  var data = null;
  var shown = null;
  // The frame shown: a slider stop of the paper's reduction, or the frame
  // of another reduction (after the stops).
  var current = null;

  // The sticky bar's height, so that a section jumped to starts below it.
  function barHeight() {
    document.documentElement.style.setProperty("--bar", controls.offsetHeight + "px");
  }
  barHeight();
  window.addEventListener("resize", barHeight);
  // Folded tables print unfolded.
  window.addEventListener("beforeprint", function () {
    Array.prototype.forEach.call(document.querySelectorAll("details"), function (d) { d.open = true; });
  });

  function show(k) {
    var stop = data.stops[k];
    current = k;
    out.textContent = stop.shown;
    out.setAttribute("data-value", stop.alpha === null ? "" : stop.alpha);
    out.setAttribute("data-stamp", stop.alpha === null ? stop.reduction : "alpha-" + stop.alpha);
    if (stop.alpha !== null) field.value = stop.alpha;
    regime.textContent = stop.regime + (stop.at_h ? " (α = h: last level with three-term averages)" : "");
    slider.setAttribute("aria-valuetext", stop.alpha === null ? "alpha not used" : "alpha " + stop.alpha);
    data.figures.forEach(function (f, j) {
      // A figure of the paper's reduction only follows the slider.
      var frame = f.frames[f.paper ? Number(slider.value) : k];
      f.parts.forEach(function (part, i) {
        if (shown[j][i] !== frame[i]) {
          document.getElementById(f.prefix + part).innerHTML = data.strings[frame[i]];
          shown[j][i] = frame[i];
        }
      });
    });
    Object.keys(stop.cells).forEach(function (id) {
      var cells = document.querySelectorAll("#" + id + " td");
      var exact = stop.cells[id][0], text = stop.cells[id][1];
      for (var i = 0; i < cells.length; i++) {
        cells[i].textContent = text[i];
        cells[i].setAttribute("data-value", exact[i]);
        cells[i].classList.toggle("absent", exact[i] === "null");
      }
    });
    Object.keys(stop.bar).forEach(function (id) {
      var e = document.getElementById(id);
      e.textContent = stop.bar[id][1];
      e.setAttribute("data-value", stop.bar[id][0]);
    });
    document.body.classList.toggle("at-h", stop.at_h);
    var files = data.files_at[k] !== null;
    var command = "t2spline run JOB " + (stop.alpha === null ? "--type-reduction " + stop.reduction : "--alpha " + stop.alpha);
    Array.prototype.forEach.call(document.querySelectorAll("button.dl[data-file]"), function (b) {
      b.disabled = !files;
      b.title = files ? "" : "Not in the report here; " + command + " writes it.";
    });
    if (!files) {
      note.textContent = data.files_note + "; here: " + command + " [--csv DIR].";
    }
  }

  // The slider stop nearest to a typed alpha (alphas are compared, not
  // computed); the frames of other reductions have no alpha.
  function nearest(value) {
    var best = 0;
    data.stops.forEach(function (s, k) {
      if (s.alpha !== null && Math.abs(Number(s.alpha) - value) < Math.abs(Number(data.stops[best].alpha) - value)) best = k;
    });
    return best;
  }

  function fromField() {
    var v = Number(field.value);
    if (field.value === "" || !(v >= 0 && v <= 1)) {
      note.textContent = "α is a number from 0 to 1.";
      return;
    }
    var k = nearest(v);
    slider.value = String(k);
    var typed = field.value;
    show(k);
    if (Number(data.stops[k].alpha) !== v) {
      note.textContent = "No stop at α = " + typed + ": showing the nearest, α = " + data.stops[k].alpha +
        " (stops every " + data.step + " and at every h). For α = " + typed + " exactly: t2spline run JOB --alpha " + typed + ".";
    } else if (data.files_at[k] !== null) {
      note.textContent = "";
    }
  }

  // A downloadable file at a stop (the shown one by default): its template
  // joined with the stop's numbers. The numbers of all files come as one
  // list: a string is a number, an integer repeats an earlier one (that many
  // places after the last repeated).
  function fileText(name, k) {
    var at = data.files_at[k === undefined ? current : k];
    if (at === null) return null;
    var stop = data.downloads.stops[at];
    var table = [], values = [], last = 0;
    stop.v.forEach(function (e) {
      if (typeof e === "string") {
        table.push(e);
        values.push(e);
      } else {
        last += e;
        values.push(table[last]);
      }
    });
    var next = 0, files = data.downloads.files;
    for (var f = 0; f < files.length; f++) {
      var pieces = files[f].templates[stop.t[f]], s = "";
      for (var i = 0; i < pieces.length; i++) {
        s += pieces[i];
        if (i + 1 < pieces.length) s += values[next++];
      }
      if (files[f].name === name) return s;
    }
    return null;
  }

  function svgText(name) {
    var svg = document.querySelector("figure[data-name='" + name + "'] svg");
    return new XMLSerializer().serializeToString(svg);
  }

  // PNG byte layout: a pHYs chunk (pixels per metre) after the 33-byte header.
  var crcTable = null;
  function crc32(bytes) {
    if (!crcTable) {
      crcTable = [];
      for (var n = 0; n < 256; n++) {
        var c = n;
        for (var k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
        crcTable[n] = c >>> 0;
      }
    }
    var crc = 0xffffffff;
    for (var i = 0; i < bytes.length; i++) crc = crcTable[(crc ^ bytes[i]) & 0xff] ^ (crc >>> 8);
    return (crc ^ 0xffffffff) >>> 0;
  }
  function withDpi(png, perMetre) {
    var chunk = new Uint8Array(21), view = new DataView(chunk.buffer);
    view.setUint32(0, 9);
    chunk.set([0x70, 0x48, 0x59, 0x73], 4);
    view.setUint32(8, perMetre);
    view.setUint32(12, perMetre);
    chunk[16] = 1;
    view.setUint32(17, crc32(chunk.subarray(4, 17)));
    var outBytes = new Uint8Array(png.length + 21);
    outBytes.set(png.subarray(0, 33), 0);
    outBytes.set(chunk, 33);
    outBytes.set(png.subarray(33), 54);
    return outBytes;
  }
  // The figure as PNG at 3 pixels per unit (1920 pixels for a 640-unit
  // figure), marked 300 dpi, as t2spline plot writes it.
  function pngBytes(name) {
    var svg = svgText(name);
    var el = document.querySelector("figure[data-name='" + name + "'] svg");
    var w = Number(el.getAttribute("width")), h = Number(el.getAttribute("height"));
    return new Promise(function (resolve, reject) {
      var img = new Image();
      img.onload = function () {
        var canvas = document.createElement("canvas");
        canvas.width = Math.round(3 * w);
        canvas.height = Math.round(3 * h);
        var ctx = canvas.getContext("2d");
        ctx.fillStyle = "#fff";
        ctx.fillRect(0, 0, canvas.width, canvas.height);
        ctx.drawImage(img, 0, 0, canvas.width, canvas.height);
        canvas.toBlob(function (blob) {
          blob.arrayBuffer().then(function (b) { resolve(withDpi(new Uint8Array(b), 11811)); }, reject);
        }, "image/png");
      };
      img.onerror = function () { reject(new Error("the figure could not be drawn")); };
      img.src = "data:image/svg+xml;charset=utf-8," + encodeURIComponent(svg);
    });
  }

  function save(name, blob) {
    var a = document.createElement("a");
    a.href = URL.createObjectURL(blob);
    a.download = name;
    document.body.appendChild(a);
    a.click();
    setTimeout(function () { URL.revokeObjectURL(a.href); a.remove(); }, 1000);
  }
  // "result-alpha-0.8.json", or "result-centroid.json" for a reduction
  // that does not use alpha.
  function stamped(name) {
    return name.replace(/\.(json|csv|svg|png)$/, "-" + out.getAttribute("data-stamp") + ".$1");
  }

  // The paper's reduction follows the slider; each other one has a frame of
  // its own (it does not use alpha), named in data.reductions.
  function showReduction() {
    var frame = null;
    data.reductions.forEach(function (r) {
      if (r.name === select.value) frame = r.frame;
    });
    var paper = frame === null;
    slider.disabled = !paper;
    field.disabled = !paper;
    Array.prototype.forEach.call(buttons, function (b) { b.disabled = !paper; });
    note.textContent = "";
    show(paper ? Number(slider.value) : frame);
  }

  Array.prototype.forEach.call(document.querySelectorAll("button.dl"), function (b) {
    b.addEventListener("click", function () {
      var file = b.getAttribute("data-file"), svg = b.getAttribute("data-svg"), png = b.getAttribute("data-png");
      if (file && data) {
        save(stamped(file), new Blob([fileText(file)], { type: file.endsWith(".json") ? "application/json" : "text/csv" }));
      } else if (svg) {
        save(stamped(svg + ".svg"), new Blob([svgText(svg)], { type: "image/svg+xml" }));
      } else if (png) {
        pngBytes(png).then(function (bytes) { save(stamped(png + ".png"), new Blob([bytes], { type: "image/png" })); });
      }
    });
  });

  function ready() {
    shown = data.figures.map(function (f) {
      return f.frames[f.paper ? Number(slider.value) : data.initial].slice();
    });
    select.disabled = false;
    slider.addEventListener("input", function () {
      note.textContent = "";
      show(Number(slider.value));
    });
    field.addEventListener("change", fromField);
    Array.prototype.forEach.call(buttons, function (b) {
      b.addEventListener("click", function () {
        slider.value = b.getAttribute("data-stop");
        note.textContent = "";
        show(Number(slider.value));
      });
    });
    select.addEventListener("change", showReduction);
    showReduction();
    document.body.setAttribute("data-ready", "1");
  }

  // For scripts and tests: the texts behind each download.
  window.t2splineReport = {
    fileText: fileText,
    svgText: svgText,
    pngBytes: pngBytes,
    ready: function () { return data !== null; }
  };

  var packed = document.getElementById("report-data").textContent.trim();
  var binary = atob(packed), bytes = new Uint8Array(binary.length);
  for (var i = 0; i < binary.length; i++) bytes[i] = binary.charCodeAt(i);
  new Response(new Blob([bytes]).stream().pipeThrough(new DecompressionStream("deflate"))).text().then(function (text) {
    data = JSON.parse(text);
    ready();
  }, function (e) {
    note.textContent = "This browser cannot unpack the report's data (" + e + "); the page shows the starting α only.";
  });
})();
