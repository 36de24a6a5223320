"""The robustness report that compare/plots/report_figures.py writes from the output of `eccd report`.

common    the report's name, its exit on bad input, the plotting packages, the input schema
inputs    reading and checking results.csv, meta.json and failure_map.csv
fmt       number and table formatting, per-pipeline summaries, Data
figures   the figures and their manifest (figures.json)
vocab     what the sections share: family groups, table titles, levels, reason classes
sections  the sections on the guarded face
verdict   the verdict in detail and its headline
faces     the two faces: as published, the guard's record, the papers' claims, the verdict's opening
build     report.md from the sections; figures.json written and checked
"""
