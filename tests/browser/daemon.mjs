// Starts the toond under test for a browser test and waits for its
// "listening on <url>" line; resolves to { child, url }.
import { spawn } from 'node:child_process';
import { createInterface } from 'node:readline';

export function startDaemon(toondBinary, listen, dataDir, timeoutMs) {
  const child = spawn(toondBinary, ['--listen', listen, '--data-dir', dataDir], { stdio: ['ignore', 'pipe', 'pipe'] });
  child.stderr.on('data', (d) => process.stderr.write(`[toond] ${d}`));
  return new Promise((resolve, reject) => {
    const timer = setTimeout(() => reject(new Error('toond did not print its listening line')), timeoutMs);
    child.on('exit', (code) => reject(new Error(`toond exited early with ${code}`)));
    createInterface({ input: child.stdout }).on('line', (line) => {
      const m = /listening on (http:\/\/\S+)/.exec(line);
      if (m) {
        clearTimeout(timer);
        resolve({ child, url: m[1] });
      }
    });
  });
}
