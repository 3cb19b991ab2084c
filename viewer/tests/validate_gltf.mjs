// Runs the Khronos glTF Validator (npm gltf-validator) on each file given and
// fails when it reports an error or a warning. Usage:
//   node validate_gltf.mjs FILE.gltf|FILE.glb ...
import { readFileSync } from "node:fs";
import { basename } from "node:path";
import validator from "gltf-validator";

let failed = false;
for (const path of process.argv.slice(2)) {
  const report = await validator.validateBytes(new Uint8Array(readFileSync(path)), {
    uri: basename(path),
    maxIssues: 20,
    externalResourceFunction: (uri) => Promise.reject(new Error(`external resource ${uri}: none expected`)),
  });
  const { numErrors, numWarnings, numInfos, messages } = report.issues;
  const summary = `${numErrors} errors, ${numWarnings} warnings, ${numInfos} infos`;
  if (numErrors > 0 || numWarnings > 0) {
    failed = true;
    console.log(`FAIL: ${path}: ${summary}`);
    for (const m of messages) if (m.severity <= 1) console.log(`  ${m.code} at ${m.pointer}: ${m.message}`);
  } else {
    console.log(`ok: ${path}: ${summary}`);
  }
}
process.exit(failed ? 1 : 0);
