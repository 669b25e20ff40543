// The page's URL query becomes the lab's command line (pba_web_page, cmake/PbaLab.cmake), so a link
// opens a prepared setup: pba-cloth.html?scene=flag&set=wind=8 runs `pba-cloth --scene flag --set wind=8`.
// Every frame the lab writes its status (scene, parameters, metrics: framework/app/ui_status.cpp) to
// MEMFS; window.pbaStatus() reads it, and with ?report=N the page logs it once after N frames
// ("PBA_STATUS {...}"), which is how the browser tests read what the query did.
var Module = typeof Module !== 'undefined' ? Module : {};
(function () {
  var valued = ['scene', 'set', 'seed', 'dt', 'substeps', 'time-scale'];
  var flags = ['lecture'];
  var args = [];
  var query = new URLSearchParams(typeof location !== 'undefined' ? location.search : '');
  query.forEach(function (value, key) {
    if (valued.indexOf(key) >= 0) args.push('--' + key, value);
    else if (flags.indexOf(key) >= 0 && value !== '0') args.push('--' + key);
  });
  Module.arguments = (Module.arguments || []).concat(args);
  var statusPath = '/tmp/pba-status.json';
  Module.preRun = [].concat(Module.preRun || [], function () { ENV.PBA_UI_STATUS = statusPath; });
  var readStatus = function () {
    try { return JSON.parse(FS.readFile(statusPath, { encoding: 'utf8' })); } catch (e) { return null; }
  };
  if (typeof window !== 'undefined') {
    window.pbaStatus = readStatus;
    var report = parseInt(query.get('report') || '0', 10);
    if (report > 0) {
      var poll = function () {
        var s = readStatus();
        if (s && s.frame >= report) console.log('PBA_STATUS ' + JSON.stringify(s));
        else requestAnimationFrame(poll);
      };
      requestAnimationFrame(poll);
    }
  }
})();
