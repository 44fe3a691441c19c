// Loaded after require.js and before embed-amd.js (@jupyter-widgets/html-manager) on
// the pages of executed notebooks; see docs/conf.py.
(function () {
  "use strict";
  // 1. Where requirejs finds the widget modules that html-manager asks for: the
  //    copies of pythreejs' scripts shipped in _static/pentanb-widgets/, not a CDN.
  var here = document.currentScript.src.replace(/[^/]*$/, "");
  window.require.config({
    paths: {
      "jupyter-threejs": here + "pentanb-widgets/jupyter-threejs",
      three: here + "pentanb-widgets/three",
    },
  });

  // 2. html-manager typesets widget labels with MathJax 2's MathJax.Hub.Queue
  //    whenever window.MathJax exists; the site ships MathJax 3, which has no Hub.
  //    Give it one that typesets with MathJax 3, before html-manager draws (it
  //    draws on "load"; this listener is registered first).
  function typeset(element) {
    var mj = window.MathJax;
    var ready = mj.startup && mj.startup.promise ? mj.startup.promise : Promise.resolve();
    ready
      .then(function () {
        return mj.typesetPromise ? mj.typesetPromise(element ? [element] : undefined) : null;
      })
      .catch(function (error) {
        console.warn("pentanb: MathJax could not typeset a widget label", error);
      });
  }
  function shim() {
    var mj = window.MathJax;
    if (mj && !mj.Hub) {
      mj.Hub = {
        Queue: function (job) {
          typeset(job && job[2]);
        },
      };
    }
  }
  shim();
  document.addEventListener("DOMContentLoaded", shim);
  window.addEventListener("load", shim);
})();
