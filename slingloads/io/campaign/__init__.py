"""Input and output of the campaign: its Study parameters and sheets, the reader (the towed
system from the airframe sheets), the run cache on disk, the Excel/PNG/Parquet report and the
plots."""
