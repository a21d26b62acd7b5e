// A directory served on 127.0.0.1 by `python3 -m http.server` on a free port, as
// platform/debian/run-demo --web serves the page: {server, port}, port a promise.
import {spawn} from 'node:child_process';

export function serve(dir) {
  const server = spawn('python3', ['-u', '-m', 'http.server', '0', '--bind', '127.0.0.1', '--directory', dir],
                       {stdio: ['ignore', 'pipe', 'pipe']});
  let log = '';
  server.stderr.on('data', (d) => { log = (log + d).slice(-5000); });
  const port = new Promise((resolve, reject) => {
    let out = '';
    server.stdout.on('data', (d) => {
      out += d;
      const m = /port (\d+)/.exec(out);
      if (m) resolve(Number(m[1]));
    });
    server.on('exit', (code) => reject(new Error(`python3 -m http.server exited (${code}): ${log}`)));
    setTimeout(() => reject(new Error('python3 -m http.server did not start within 20 s')), 20000);
  });
  return {server, port};
}
