solar1 solar2 solar3
solar4 solar5 solar6
