"""The performance report that bench/performance_report.py writes (reports/performance.md).

targets       the limits: per row, per set of scenes, per ratio of two rows, per independent scene
tools         time and ratio formatting, subprocesses, the machine, perf profiles, answer text
sections      the animation and FCL sections; the set and ratio targets' verdicts and tables
steps         after the main run: target verdicts, the target rows re-run alone, profiles
certificates  checking against proving per certificate kind
write         reports/performance.md, one helper per part
"""
