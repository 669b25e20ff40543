// The page's URL query becomes the lab's command line (pba_web_page, cmake/PbaLab.cmake), so a link
// opens a prepared setup: pba-cloth.html?scene=flag&set=wind=8 runs `pba-cloth --scene flag --set wind=8`.
// Every frame the lab writes its status (scene, parameters, metrics: framework/app/ui_status.cpp) to
// MEMFS; window.pbaStatus() reads it, and with ?report=N the page logs it once after N frames
// ("PBA_STATUS {...}"), which is how the browser tests read what the query did.
// Without ?size=WxH the lab takes the page's width and its height less the line under the canvas
// (#note, cmake/web/shell.html), and follows the page when it is resized. "Open a file" copies the
// picked file into the page's file system (/picked/NAME) and says the path to give a model field or
// the scene file field: a page cannot read the disk by path.
var Module = typeof Module !== 'undefined' ? Module : {};
(function () {
  var valued = ['scene', 'set', 'seed', 'dt', 'substeps', 'time-scale', 'size'];
  var flags = ['lecture'];
  var args = [];
  var query = new URLSearchParams(typeof location !== 'undefined' ? location.search : '');
  query.forEach(function (value, key) {
    if (valued.indexOf(key) >= 0) args.push('--' + key, value);
    else if (flags.indexOf(key) >= 0 && value !== '0') args.push('--' + key);
  });
  var pageSize = function () {
    var note = typeof document !== 'undefined' ? document.getElementById('note') : null;
    var below = note ? note.offsetHeight : 0;
    // The lab's smallest window (kMinWindowWidth x kMinWindowHeight, app/command_line.h).
    return [Math.max(320, window.innerWidth), Math.max(240, window.innerHeight - below)];
  };
  if (typeof window !== 'undefined' && !query.has('size')) {
    var start = pageSize();
    args.push('--size', start[0] + 'x' + start[1]);
    window.addEventListener('resize', function () {
      var now = pageSize();
      if (typeof Browser !== 'undefined' && Module.canvas) Browser.setCanvasSize(now[0], now[1]);
    });
  }
  Module.arguments = (Module.arguments || []).concat(args);
  var statusPath = '/tmp/pba-status.json';
  Module.preRun = [].concat(Module.preRun || [], function () { ENV.PBA_UI_STATUS = statusPath; });
  var readStatus = function () {
    try { return JSON.parse(FS.readFile(statusPath, { encoding: 'utf8' })); } catch (e) { return null; }
  };
  if (typeof window !== 'undefined') {
    window.pbaStatus = readStatus;
    var pick = document.getElementById('pick');
    if (pick) pick.addEventListener('change', function () {
      var file = pick.files[0];
      if (!file) return;
      file.arrayBuffer().then(function (bytes) {
        var path = '/picked/' + file.name.replace(/[^A-Za-z0-9._-]/g, '_');
        try { FS.mkdir('/picked'); } catch (e) { /* already there */ }
        FS.writeFile(path, new Uint8Array(bytes));
        document.getElementById('picked').textContent = 'copied to ' + path +
          ': type that path into a model field (skeleton, model, ...) or the scene file field';
      });
    });
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
