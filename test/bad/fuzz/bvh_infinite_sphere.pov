// A sphere of infinite radius among four others: its bounding box is infinite and its centre
// NaN, which the bounding hierarchy's binning once turned into a negative bin index.
sphere { <-2, 0, 0>, 0.5 }
sphere { <0, 0, 0>, -1e400 }
sphere { <1, 0, 0>, 0.5 }
sphere { <2, 0, 0>, 0.5 }
sphere { <3, 0, 0>, 0.5 }
