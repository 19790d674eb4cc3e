//! [`Codes`]: the codes of a merged string or JSON column, in the narrowest
//! unsigned type that holds them.

/// The codes of a merged string or JSON column, one byte each while the table
/// has at most 255 entries, two up to 65 535, else four, widened as the table
/// grows: the codes are held until the column's object array is made, and a
/// sweep has 15 string columns (60 bytes per point at four bytes a code).
pub enum Codes {
    /// Tables of up to 255 entries.
    U8(Vec<u8>),
    /// Tables of up to 65 535 entries.
    U16(Vec<u16>),
    /// Larger tables.
    U32(Vec<u32>),
}

impl Codes {
    /// `n` missing values (code 0).
    pub(super) fn missing(n: usize) -> Self {
        Codes::U8(vec![0; n])
    }

    pub(super) fn len(&self) -> usize {
        match self {
            Codes::U8(v) => v.len(),
            Codes::U16(v) => v.len(),
            Codes::U32(v) => v.len(),
        }
    }

    /// The code of row `i`.
    #[inline]
    pub(super) fn get(&self, i: usize) -> u32 {
        match self {
            Codes::U8(v) => u32::from(v[i]),
            Codes::U16(v) => u32::from(v[i]),
            Codes::U32(v) => v[i],
        }
    }

    /// Widened, if needed, to hold codes up to `max`.
    pub(super) fn fit(&mut self, max: usize) {
        let wide: Option<Codes> = match self {
            Codes::U8(v) if max > usize::from(u8::MAX) => Some(if max <= usize::from(u16::MAX) {
                Codes::U16(v.iter().map(|&c| u16::from(c)).collect())
            } else {
                Codes::U32(v.iter().map(|&c| u32::from(c)).collect())
            }),
            Codes::U16(v) if max > usize::from(u16::MAX) => {
                Some(Codes::U32(v.iter().map(|&c| u32::from(c)).collect()))
            }
            _ => None,
        };
        if let Some(w) = wide {
            *self = w;
        }
    }

    /// Writes a chunk's codes, mapped by `map` (chunk code → merged code, all
    /// within the width: [`Codes::fit`] first), from row `at`.
    pub(super) fn put(&mut self, at: usize, codes: &[u32], map: &[u32]) {
        let mapped = codes.iter().map(|&c| map[c as usize]);
        match self {
            Codes::U8(v) => {
                for (x, c) in v[at..at + codes.len()].iter_mut().zip(mapped) {
                    *x = c as u8;
                }
            }
            Codes::U16(v) => {
                for (x, c) in v[at..at + codes.len()].iter_mut().zip(mapped) {
                    *x = c as u16;
                }
            }
            Codes::U32(v) => {
                for (x, c) in v[at..at + codes.len()].iter_mut().zip(mapped) {
                    *x = c;
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::Codes;

    #[test]
    fn codes_widen_as_the_table_grows() {
        let map: Vec<u32> = (0..70_000).collect();
        let mut c = Codes::missing(5);
        c.fit(3);
        c.put(0, &[1, 2], &map);
        assert!(matches!(c, Codes::U8(_)));
        c.fit(300);
        c.put(2, &[299], &map);
        assert!(matches!(c, Codes::U16(_)));
        c.fit(70_000);
        c.put(3, &[69_999], &map);
        assert!(matches!(c, Codes::U32(_)));
        let all: Vec<u32> = (0..c.len()).map(|i| c.get(i)).collect();
        assert_eq!(all, [1, 2, 299, 69_999, 0]);
    }
}
