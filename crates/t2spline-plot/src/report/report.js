// t2spline report: the alpha slider and the type-reduction selector. Every number and every curve shown was
// computed by t2spline and stored in the data block; this script only swaps
// them in (it does no arithmetic on the method).
(function () {
  "use strict";
  var data = JSON.parse(document.getElementById("report-data").textContent);
  var slider = document.getElementById("alpha");
  var out = document.getElementById("alpha-value");
  var regime = document.getElementById("regime");
  var shown = data.figures.map(function (f) {
    return f.frames[data.initial].slice();
  });

  function show(k) {
    var stop = data.stops[k];
    out.textContent = stop.alpha;
    regime.textContent = stop.regime + (stop.at_h ? " (α = h: last level with three-term averages)" : "");
    slider.setAttribute("aria-valuetext", "alpha " + stop.alpha);
    data.figures.forEach(function (f, j) {
      var frame = f.frames[k];
      f.parts.forEach(function (part, i) {
        if (shown[j][i] !== frame[i]) {
          document.getElementById(f.prefix + part).innerHTML = data.strings[frame[i]];
          shown[j][i] = frame[i];
        }
      });
    });
    Object.keys(stop.cells).forEach(function (id) {
      var cells = document.querySelectorAll("#" + id + " td");
      var values = stop.cells[id];
      for (var i = 0; i < cells.length; i++) {
        cells[i].textContent = values[i];
        cells[i].classList.toggle("absent", values[i] === "null");
      }
    });
    document.body.classList.toggle("at-h", stop.at_h);
  }

  // The type reduction: the paper's follows the slider; each other one has
  // a frame of its own (it does not use alpha), named in data.reductions.
  var select = document.getElementById("reduction");
  var buttons = document.querySelectorAll("button[data-stop]");

  function showReduction() {
    var frame = null;
    data.reductions.forEach(function (r) {
      if (r.name === select.value) {
        frame = r.frame;
      }
    });
    var paper = frame === null;
    slider.disabled = !paper;
    Array.prototype.forEach.call(buttons, function (b) {
      b.disabled = !paper;
    });
    show(paper ? Number(slider.value) : frame);
  }

  slider.addEventListener("input", function () {
    show(Number(slider.value));
  });
  Array.prototype.forEach.call(buttons, function (b) {
    b.addEventListener("click", function () {
      slider.value = b.getAttribute("data-stop");
      show(Number(slider.value));
    });
  });
  select.addEventListener("change", showReduction);
  showReduction();
})();
