#!/usr/bin/env python3
"""Writes the seed corpora of the simulator's readers (tests/fuzz/corpus/{trial,trial_report,script,hid_descriptor,
cohort_csv}) after their documented formats: docs/file-formats.md ("Trial files", "Trial reports", the script),
docs/haptics-protocol.md ("The report descriptor": its 238 bytes, protocol 2's, are read from the listing) and
hs/anatomy/TrainingData.h (the cohort CSV).
    python3 tests/fuzz/make-sim-seeds.py
"""
import json
import os
import re
import struct

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.dirname(os.path.dirname(here))
corpus = os.path.join(here, 'corpus')


def write(folder, name, data):
    os.makedirs(os.path.join(corpus, folder), exist_ok=True)
    with open(os.path.join(corpus, folder, name), 'wb') as f:
        f.write(data if isinstance(data, bytes) else data.encode())


header = {
    'format': 'hysteroscene-trial', 'version': 2, 'sceneSha256': 'ab' * 32, 'seed': 7,
    'physics': {'engine': 'hs::mechanics corotational FEM', 'stepS': 0.005, 'solverIterations': 8},
    'exercise': 'exploration',
    'scope': {'opticDeg': 30, 'diameterMm': 2.9, 'fieldOfViewDeg': 90, 'focusNearMm': 2, 'focusFarMm': 40},
    'fluid': {'pumpPressureKpa': 10.7, 'meanArterialPressureKpa': 11.3, 'deficitWarningMl': 1000,
              'deficitLimitMl': 2500},
    'device': 'scripted', 'startedUtc': '2026-12-03T12:00:00Z'}
text = json.dumps(header, separators=(',', ':')).encode()
samples = b''.join(struct.pack('<Q7dII', tick, -5.0 + tick, 1.0, -1.0, 0.0, 0.0, 1.0, 0.3, tick % 2, 0)
                   for tick in range(3))
trial = b'HSTRIAL1' + struct.pack('<I', len(text)) + text + struct.pack('<Q', 3) + samples
write('trial', 'three-samples.trial', trial)
write('trial', 'truncated.trial', trial[:60])

frames = [{'t': 0, 'insertionMm': -5, 'pitchDeg': 0, 'yawDeg': 0, 'rollDeg': 0, 'cameraRollDeg': 0, 'inflow': 1,
           'outflow': 0.3, 'buttons': 0},
          {'t': 1.5, 'insertionMm': 30, 'pitchDeg': 10, 'yawDeg': -5, 'rollDeg': 20, 'cameraRollDeg': 0,
           'inflow': 1, 'outflow': 0.5, 'buttons': 1}]
write('script', 'two-keyframes.json', json.dumps({'format': 'hysteroscene-script', 'version': 1,
                                                  'keyframes': frames}, indent=1))
write('script', 'no-keyframes.json', json.dumps({'format': 'hysteroscene-script', 'version': 1, 'keyframes': []}))

listing = open(os.path.join(root, 'docs', 'haptics-protocol.md')).read()
block = listing[listing.index('## The report descriptor'):]
block = block[block.index('```') + 3:]
block = block[:block.index('```')]
descriptor = bytearray()
for line in block.splitlines():
    m = re.match(r'\s*\d+\s+((?:[0-9A-F]{2} )*[0-9A-F]{2})\s', line + ' ')
    if m:
        descriptor += bytes(int(b, 16) for b in m.group(1).split())
assert len(descriptor) == 238, len(descriptor)  # protocol 2's
write('hid_descriptor', 'protocol.bin', bytes(descriptor))
write('hid_descriptor', 'truncated.bin', bytes(descriptor[:99]) + b'\x27\x01')  # a 4-byte item cut after 1
write('hid_descriptor', 'long-item.bin', b'\xfe\x02\x10\x01\x02')

write('cohort_csv', 'one-row.csv', 'file,ageYears,parity,gravidity,heightCm,weightKg,menopausal\n'
                                   'a.obj,34,1,2,168,61,no\na.obj,58,2,2,160,70,yes\n')
write('cohort_csv', 'bad-values.csv', 'file,ageYears,parity,gravidity,heightCm,weightKg,menopausal\n'
                                      'a.obj,1e400,-1,2.5,168,61,maybe\n../a.obj,34,1,2,168,61,no\n')

report_header = {k: v for k, v in header.items() if k not in ('format', 'version')}
report_header['exercise'] = 'polypectomy'
report_header['fluid'] = dict(header['fluid'], medium='saline', elderlyOrComorbid=False)
metrics = {
    'timeS': 0.2, 'pathLengthMm': 3.5, 'cavitySurfaceVisualizedPercent': 12.5,
    'targets': [{'name': 'fundus', 'visualizedPercent': 40, 'seen': False, 'firstSeenS': -1}],
    'horizonErrorMeanDeg': 2, 'horizonErrorMaxDeg': 5, 'wallContacts': 1, 'peakForceN': 0.25, 'contactTimeS': 0.1,
    'perforations': [{'timeS': 0.1, 'locationMm': [1, 2, 3], 'depthMm': 1.5, 'region': 'myometrium',
                      'falsePassage': False}],
    'timeAboveMeanArterialPressureS': 0, 'maxPressureKpa': 9.5, 'inflowMl': 4, 'outflowMl': 3, 'deficitMl': 1,
    'intravasationMl': 0.5, 'bloodLossMl': 0.01, 'finalPumpPressureKpa': 11.4, 'deficitWarning': False,
    'deficitLimitReached': False, 'redOutTimeS': 0,
    'pathologies': [{'id': 'polyp-1', 'kind': 'polyp', 'seen': True, 'found': False, 'foundS': -1}],
    'falseMarks': 0,
    'resection': {'pathologies': [{'id': 'polyp-1', 'kind': 'polyp', 'volumeMl': 0.24, 'removedMl': 0.12,
                                   'removedPercent': 50}],
                  'healthyRemovedMl': 0.01, 'deepestMyometriumMm': 0.5, 'perforatingCuts': 0, 'cutEvents': 3,
                  'removedTets': 20, 'chips': 1, 'chipsMade': 2, 'chipsCarriedOut': 1, 'chipsLeft': 1,
                  'cuttingTimeS': 0.1, 'resectionTimeS': 0.1, 'firstCutS': 0.1, 'loopPathMm': 4,
                  'coagulationTimeS': 0}}
report = {'format': 'hysteroscene-trial-report', 'version': 2, 'header': report_header, 'samples': 200,
          'explorationComplete': False, 'diagnosisComplete': False, 'metrics': metrics,
          'series': {'timeS': [0, 0.1, 0.2], 'forceN': [0, 0.25, 0], 'pressureKpa': [0, 5, 9.5],
                     'deficitMl': [0, 0.5, 1], 'bloodLossMl': [0, 0, 0.01], 'pumpSetKpa': [10.7, 10.7, 11.4]},
          'surface': {'aroundDeg': [-90, 0, 90], 'alongMm': [1, 2, 3], 'seen': [True, False, True]}}
write('trial_report', 'operative.json', json.dumps(report, separators=(',', ':')))
first = dict(report, version=1, series={k: v for k, v in report['series'].items() if k != 'pumpSetKpa'})
write('trial_report', 'version-1.json', json.dumps(first, separators=(',', ':')))
write('trial_report', 'columns-unequal.json',
      json.dumps(dict(report, series=dict(report['series'], forceN=[0])), separators=(',', ':')))
