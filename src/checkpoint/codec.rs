//! The checkpoint's binary encoding: little-endian values one after another, sequences with
//! their length first (u64), `Option` with a presence byte. Every read checks that the bytes are
//! there, so a truncated or foreign file is an error, never a panic or a huge allocation.

/// A value the checkpoint writes and reads back bit for bit.
pub trait Codec: Sized {
    fn put(&self, out: &mut Vec<u8>);
    fn get(r: &mut Reader) -> anyhow::Result<Self>;
}

/// Reads values from a checkpoint's bytes.
pub struct Reader<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl<'a> Reader<'a> {
    pub fn new(bytes: &'a [u8]) -> Reader<'a> {
        Reader { bytes, at: 0 }
    }

    fn take(&mut self, n: usize) -> anyhow::Result<&'a [u8]> {
        let end = self.at.checked_add(n).filter(|&e| e <= self.bytes.len());
        let end = end.ok_or_else(|| anyhow::anyhow!("the checkpoint ends early (truncated?)"))?;
        let s = &self.bytes[self.at..end];
        self.at = end;
        Ok(s)
    }

    /// A sequence's length, checked against the bytes left (each item takes one byte at least).
    fn len(&mut self) -> anyhow::Result<usize> {
        let n = u64::get(self)?;
        anyhow::ensure!(
            n <= (self.bytes.len() - self.at) as u64,
            "the checkpoint ends early (truncated or damaged?): it names {n} items where fewer bytes \
             are left"
        );
        Ok(n as usize)
    }

    /// How many bytes were read.
    pub fn position(&self) -> usize {
        self.at
    }

    /// Whether every byte was read.
    pub fn at_end(&self) -> bool {
        self.at == self.bytes.len()
    }
}

/// Write `value`.
pub fn put<T: Codec>(out: &mut Vec<u8>, value: &T) {
    value.put(out);
}

macro_rules! numbers {
    ($($t:ty),*) => {$(
        impl Codec for $t {
            fn put(&self, out: &mut Vec<u8>) {
                out.extend_from_slice(&self.to_le_bytes());
            }
            fn get(r: &mut Reader) -> anyhow::Result<Self> {
                let b = r.take(std::mem::size_of::<$t>())?;
                Ok(<$t>::from_le_bytes(b.try_into().expect("taken to size")))
            }
        }
    )*};
}

numbers!(u8, u32, u64, i64, f64);

impl Codec for bool {
    fn put(&self, out: &mut Vec<u8>) {
        out.push(u8::from(*self));
    }
    fn get(r: &mut Reader) -> anyhow::Result<Self> {
        match u8::get(r)? {
            0 => Ok(false),
            1 => Ok(true),
            b => anyhow::bail!("the checkpoint has {b} where a flag is 0 or 1 (damaged?)"),
        }
    }
}

impl Codec for usize {
    fn put(&self, out: &mut Vec<u8>) {
        (*self as u64).put(out);
    }
    fn get(r: &mut Reader) -> anyhow::Result<Self> {
        Ok(usize::try_from(u64::get(r)?)?)
    }
}

impl<T: Codec, const N: usize> Codec for [T; N] {
    fn put(&self, out: &mut Vec<u8>) {
        for x in self {
            x.put(out);
        }
    }
    fn get(r: &mut Reader) -> anyhow::Result<Self> {
        let v: Vec<T> = (0..N).map(|_| T::get(r)).collect::<anyhow::Result<_>>()?;
        Ok(v.try_into().ok().expect("N items read"))
    }
}

impl<T: Codec> Codec for Vec<T> {
    fn put(&self, out: &mut Vec<u8>) {
        self.len().put(out);
        for x in self {
            x.put(out);
        }
    }
    fn get(r: &mut Reader) -> anyhow::Result<Self> {
        let n = r.len()?;
        (0..n).map(|_| T::get(r)).collect()
    }
}

impl<T: Codec> Codec for Option<T> {
    fn put(&self, out: &mut Vec<u8>) {
        self.is_some().put(out);
        if let Some(x) = self {
            x.put(out);
        }
    }
    fn get(r: &mut Reader) -> anyhow::Result<Self> {
        Ok(if bool::get(r)? {
            Some(T::get(r)?)
        } else {
            None
        })
    }
}

impl Codec for String {
    fn put(&self, out: &mut Vec<u8>) {
        self.as_bytes().to_vec().put(out);
    }
    fn get(r: &mut Reader) -> anyhow::Result<Self> {
        Ok(String::from_utf8(Vec::<u8>::get(r)?)?)
    }
}

impl<A: Codec, B: Codec> Codec for (A, B) {
    fn put(&self, out: &mut Vec<u8>) {
        self.0.put(out);
        self.1.put(out);
    }
    fn get(r: &mut Reader) -> anyhow::Result<Self> {
        Ok((A::get(r)?, B::get(r)?))
    }
}

impl<A: Codec, B: Codec, C: Codec> Codec for (A, B, C) {
    fn put(&self, out: &mut Vec<u8>) {
        self.0.put(out);
        self.1.put(out);
        self.2.put(out);
    }
    fn get(r: &mut Reader) -> anyhow::Result<Self> {
        Ok((A::get(r)?, B::get(r)?, C::get(r)?))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_come_back_bit_for_bit_and_a_short_file_is_an_error() {
        let mut out = Vec::new();
        let values: Vec<[f64; 2]> = vec![[0.1, -0.0], [f64::MIN_POSITIVE, 1e300]];
        put(&mut out, &values);
        put(&mut out, &Some("stage".to_string()));
        put(&mut out, &vec![true, false]);
        let mut r = Reader::new(&out);
        let back = Vec::<[f64; 2]>::get(&mut r).unwrap();
        assert!(
            back.iter()
                .flatten()
                .zip(values.iter().flatten())
                .all(|(a, b)| a.to_bits() == b.to_bits())
        );
        assert_eq!(
            Option::<String>::get(&mut r).unwrap().as_deref(),
            Some("stage")
        );
        assert_eq!(Vec::<bool>::get(&mut r).unwrap(), vec![true, false]);
        assert!(r.at_end());
        let mut short = Reader::new(&out[..out.len() - 3]);
        assert!(Vec::<[f64; 2]>::get(&mut short).is_ok());
        assert!(Option::<String>::get(&mut short).is_ok());
        assert!(Vec::<bool>::get(&mut short).is_err());
        // A length far beyond the file is refused before allocating.
        let mut huge = Vec::new();
        put(&mut huge, &u64::MAX);
        assert!(Vec::<f64>::get(&mut Reader::new(&huge)).is_err());
    }
}
