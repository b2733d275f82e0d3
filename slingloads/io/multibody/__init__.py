"""Input and output of the multibody model: its Study parameters and sheets, the reader (the
system and its manoeuvres from a workbook), the Excel/CSV report and the plots."""
