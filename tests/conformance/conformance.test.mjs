// The rig conformance suite, one case of cases.json at a time (suite.mjs
// compares, README.md here says what and why):
//
//   node conformance.test.mjs --pose-dump PATH [--converter PATH] --exported DIR
//        (--case NAME [--part full|levels] | --self-test)
//
// --part full: toond's vertices against three.js's at every time sampled;
// --part levels: each of toond's levels of detail within its own error of
// the full posed mesh; --self-test: the comparison fails on poses broken
// on purpose. Exit status 0 when it holds, 1 when it does not, 2 on a
// usage or loading error.
import { compareFull, compareLevels, loadCase, poseBoth, refusedAsKnown } from './suite.mjs';
import { selfTest } from './self_test.mjs';

function parseArguments(argv) {
  const options = { part: 'full' };
  for (let i = 0; i < argv.length; i++) {
    const flag = argv[i];
    const value = () => {
      if (i + 1 >= argv.length) usage(`${flag} needs a value`);
      return argv[++i];
    };
    if (flag === '--pose-dump') options.poseDump = value();
    else if (flag === '--converter') options.converter = value();
    else if (flag === '--exported') options.exported = value();
    else if (flag === '--case') options.case = value();
    else if (flag === '--part') options.part = value();
    else if (flag === '--self-test') options.selfTest = true;
    else usage(`unknown argument ${flag}`);
  }
  if (!options.poseDump || !options.exported) usage('--pose-dump and --exported are needed');
  if (!options.selfTest && !options.case) usage('give --case NAME or --self-test');
  if (!['full', 'levels'].includes(options.part)) usage(`--part is full or levels, not ${options.part}`);
  return options;
}

function usage(why) {
  console.error(`conformance: ${why}`);
  process.exit(2);
}

try {
  const options = parseArguments(process.argv.slice(2));
  let holds;
  if (options.selfTest) {
    holds = await selfTest(options);
  } else {
    const theCase = loadCase(options.case);
    if (theCase.toond_refuses) {
      holds = await refusedAsKnown(options, theCase);
    } else {
      const both = await poseBoth(options, theCase);
      holds = options.part === 'full' ? compareFull(theCase, both).holds : compareLevels(theCase, both);
    }
  }
  console.log(holds ? 'HOLDS' : 'FAILS');
  process.exit(holds ? 0 : 1);
} catch (error) {
  console.error(`conformance: ${error.stack ?? error}`);
  process.exit(2);
}
