fn main() {
    let p = std::env::args().nth(1).unwrap();
    let doc = lopdf::Document::load(&p).unwrap();
    let pages = doc.get_pages();
    for (n, _) in pages.iter().take(3) {
        let t = doc.extract_text(&[*n]).unwrap_or_default();
        println!("=== page {n}\n{}", t.chars().take(3000).collect::<String>());
    }
}
