// Validates glTF 2.0 files (.gltf with the files it refers to, or .glb) with the Khronos glTF
// validator, the npm package gltf-validator, and exits with status 1 if any has an error.
//
//   node validate_gltf.mjs --validator <npm prefix holding node_modules/gltf-validator> file...
//
// Prints one line per file (errors, warnings, infos) and every error and warning with its code,
// JSON pointer and message. Exit status: 0 all valid, 1 an error in some file, 2 bad usage or a file
// the validator cannot read.
import { readFile } from 'node:fs/promises';
import { createRequire } from 'node:module';
import path from 'node:path';

const args = process.argv.slice(2);
const prefixAt = args.indexOf('--validator');
if (prefixAt < 0 || prefixAt + 1 >= args.length || args.length < 3) {
    console.error('usage: node validate_gltf.mjs --validator <npm prefix> file...');
    process.exit(2);
}
const prefix = path.resolve(args[prefixAt + 1]);
const files = args.filter((_, i) => i !== prefixAt && i !== prefixAt + 1);
const validator = createRequire(path.join(prefix, 'package.json'))('gltf-validator');

const severityNames = ['error', 'warning', 'info', 'hint'];
let failed = false;
for (const file of files) {
    let report;
    try {
        report = await validator.validateBytes(new Uint8Array(await readFile(file)), {
            uri: path.basename(file),
            maxIssues: 0, // every issue, not the first 100
            writeTimestamp: false,
            // A .gltf's buffers (the .bin beside it), read as the file names them.
            externalResourceFunction: (uri) => readFile(path.resolve(path.dirname(file), decodeURIComponent(uri)))
                .then((data) => new Uint8Array(data)),
        });
    } catch (error) {
        console.error(`${file}: the validator cannot read it: ${error}`);
        process.exit(2);
    }
    const issues = report.issues;
    console.log(`${file}: ${issues.numErrors} errors, ${issues.numWarnings} warnings, ${issues.numInfos} infos ` +
                `(gltf-validator ${report.validatorVersion})`);
    for (const message of issues.messages.filter((m) => m.severity <= 1))
        console.log(`  ${severityNames[message.severity]} ${message.code} at ${message.pointer ?? '(file)'}: ${message.message}`);
    if (issues.numErrors > 0)
        failed = true;
}
process.exit(failed ? 1 : 0);
