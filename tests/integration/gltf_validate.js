// Runs the Khronos glTF validator (npm package gltf-validator) on one file and prints its issue counts as JSON.
// Usage: node gltf_validate.js MODULE_DIR FILE ; exit 0 when the file has no errors, 1 otherwise, 2 on a crash.
const fs = require('fs');
const path = require('path');
const validator = require(path.join(process.argv[2], 'node_modules', 'gltf-validator'));
const bytes = new Uint8Array(fs.readFileSync(process.argv[3]));
validator.validateBytes(bytes, {maxIssues: 100})
    .then((report) => {
        const issues = report.issues;
        console.log(JSON.stringify({
            errors: issues.numErrors,
            warnings: issues.numWarnings,
            infos: issues.numInfos,
            messages: issues.messages.map((m) => `${m.severity} ${m.code} ${m.pointer || ''}: ${m.message}`),
        }));
        process.exit(issues.numErrors === 0 ? 0 : 1);
    })
    .catch((error) => {
        console.log(JSON.stringify({crash: String(error)}));
        process.exit(2);
    });
