"""Studies: many motions described as data: case files and parameter sweeps.

Reading a case file (TOML) into a body, friction, start and loads; sweeps over grids of
parameters (spec parsing, execution locally or on Dask, storage in Parquet, reading back).

May import: :mod:`slidespin.analysis` and the layers below it, and the private root helpers.
Dask, pandas and pyarrow are imported where they are used (optional or heavy).
"""
