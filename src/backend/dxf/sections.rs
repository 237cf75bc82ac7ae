//! The sections around the entities: HEADER, CLASSES, TABLES, BLOCKS and OBJECTS.

use super::*;

impl Writer {
    pub(super) fn header(&mut self, scene: &Scene) {
        let size = Point::new(scene.width, scene.height);
        self.pair(0, "SECTION");
        self.pair(2, "HEADER");
        self.var("$ACADVER");
        self.pair(1, if self.r2000 { "AC1015" } else { "AC1009" });
        if self.r2000 {
            self.var("$ACADMAINTVER");
            self.pair(70, 6);
        }
        self.var("$DWGCODEPAGE");
        self.pair(3, "ANSI_1251");
        self.var("$INSBASE");
        self.point(10, Point::ORIGIN);
        self.var("$EXTMIN");
        self.point(10, Point::ORIGIN);
        self.var("$EXTMAX");
        self.point(10, size);
        self.var("$LIMMIN");
        self.point2(10, Point::ORIGIN);
        self.var("$LIMMAX");
        self.point2(10, size);
        self.var("$LTSCALE");
        self.pair(40, "1.0");
        self.var("$TEXTSTYLE");
        self.pair(7, STYLE);
        self.var("$CLAYER");
        self.pair(8, "0");
        self.var("$CELTYPE");
        self.pair(6, if self.r2000 { "ByLayer" } else { "BYLAYER" });
        self.var("$LUNITS");
        self.pair(70, 2);
        self.var("$LUPREC");
        self.pair(70, 3);
        self.var("$PLINEGEN");
        self.pair(70, 1);
        if self.r2000 {
            self.var("$CELWEIGHT");
            self.pair(370, -1);
            self.var("$LWDISPLAY");
            self.pair(290, 1);
            self.var("$INSUNITS");
            self.pair(70, 4);
            self.var("$MEASUREMENT");
            self.pair(70, 1);
            self.var("$PSLTSCALE");
            self.pair(70, 1);
            self.var("$DIMSTYLE");
            self.pair(2, "Standard");
            self.var("$CMLSTYLE");
            self.pair(2, "Standard");
        } else {
            self.var("$HANDLING");
            self.pair(70, 1);
        }
        let seed = self.next;
        self.var("$HANDSEED");
        self.hnd(5, seed);
        self.pair(0, "ENDSEC");
    }

    pub(super) fn classes(&mut self) {
        self.pair(0, "SECTION");
        self.pair(2, "CLASSES");
        for (name, cpp) in [
            ("ACDBDICTIONARYWDFLT", "AcDbDictionaryWithDefault"),
            ("ACDBPLACEHOLDER", "AcDbPlaceHolder"),
            ("LAYOUT", "AcDbLayout"),
        ] {
            self.pair(0, "CLASS");
            self.pair(1, name);
            self.pair(2, cpp);
            self.pair(3, "ObjectDBX Classes");
            self.pair(90, 0);
            self.pair(280, 0);
            self.pair(281, 0);
        }
        self.pair(0, "ENDSEC");
    }

    pub(super) fn table(&mut self, name: &str, handle: u32, count: usize, body: impl FnOnce(&mut Writer)) {
        self.pair(0, "TABLE");
        self.pair(2, name);
        self.hnd(5, handle);
        self.owner(0);
        self.sub("AcDbSymbolTable");
        self.pair(70, count);
        if name == "DIMSTYLE" {
            self.sub("AcDbDimStyleTable");
        }
        body(self);
        self.pair(0, "ENDTAB");
    }

    /// A table record's head: type, handle, owner, markers, name, flags.
    pub(super) fn record(&mut self, kind: &str, handle: u32, table: u32, marker: &str, name: &str) {
        self.pair(0, kind);
        self.hnd(if kind == "DIMSTYLE" { 105 } else { 5 }, handle);
        self.owner(table);
        self.sub("AcDbSymbolTableRecord");
        self.sub(marker);
        self.pair(2, name);
        self.pair(70, 0);
    }

    pub(super) fn tables(&mut self, layers: &[(String, Kind)]) {
        let r2000 = self.r2000;
        self.pair(0, "SECTION");
        self.pair(2, "TABLES");
        self.table("VPORT", h::VPORT_TABLE, 1, |w| w.vport());
        let linetypes = if r2000 { 5 } else { 3 };
        self.table("LTYPE", h::LTYPE_TABLE, linetypes, |w| {
            if r2000 {
                w.linetype(h::LTYPE_BYBLOCK, "ByBlock", "", &[]);
                w.linetype(h::LTYPE_BYLAYER, "ByLayer", "", &[]);
            }
            w.linetype(h::LTYPE_CONTINUOUS, "CONTINUOUS", "Solid line", &[]);
            let dashed = shapes::dash_array(LineType::Dashed).unwrap_or(&[]);
            w.linetype(h::LTYPE_DASHED, "DASHED", "GOST 2.303 dashed __ __ __", dashed);
            let centre = shapes::dash_array(LineType::DashDot).unwrap_or(&[]);
            w.linetype(h::LTYPE_CENTER, "CENTER", "GOST 2.303 dash-dot ____ . ____ .", centre);
        });
        self.table("LAYER", h::LAYER_TABLE, layers.len() + 1, |w| {
            w.layer(h::LAYER_0, "0", Kind::Thin);
            for (name, kind) in layers {
                let handle = w.handle();
                w.layer(handle, name, *kind);
            }
        });
        self.table("STYLE", h::STYLE_TABLE, 2, |w| {
            w.style(h::STYLE_STANDARD, "Standard", "txt");
            w.style(h::STYLE_TMM, STYLE, FONT_FILE);
        });
        self.table("VIEW", h::VIEW_TABLE, 0, |_| {});
        self.table("UCS", h::UCS_TABLE, 0, |_| {});
        self.table("APPID", h::APPID_TABLE, 1, |w| {
            w.record("APPID", h::APPID_ACAD, h::APPID_TABLE, "AcDbRegAppTableRecord", "ACAD");
        });
        self.table("DIMSTYLE", h::DIMSTYLE_TABLE, 1, |w| {
            w.record("DIMSTYLE", h::DIMSTYLE_STANDARD, h::DIMSTYLE_TABLE, "AcDbDimStyleTableRecord", "Standard");
            for (code, value) in [(40, "1.0"), (41, "2.5"), (42, "0.625"), (43, "3.75"), (44, "1.25"), (140, "2.5")] {
                w.pair(code, value);
            }
        });
        if r2000 {
            self.table("BLOCK_RECORD", h::BLOCK_RECORD_TABLE, 2, |w| {
                let t = h::BLOCK_RECORD_TABLE;
                w.record("BLOCK_RECORD", h::MODEL_RECORD, t, "AcDbBlockTableRecord", "*Model_Space");
                w.hnd(340, h::MODEL_LAYOUT);
                w.record("BLOCK_RECORD", h::PAPER_RECORD, t, "AcDbBlockTableRecord", "*Paper_Space");
                w.hnd(340, h::PAPER_LAYOUT);
            });
        }
        self.pair(0, "ENDSEC");
    }

    /// The active viewport, its view on the whole sheet.
    pub(super) fn vport(&mut self) {
        self.record("VPORT", h::VPORT_ACTIVE, h::VPORT_TABLE, "AcDbViewportTableRecord", "*Active");
        self.point2(10, Point::ORIGIN);
        self.point2(11, Point::new(1.0, 1.0));
        self.point2(12, Point::new(420.5, 297.0));
        self.point2(13, Point::ORIGIN);
        self.point2(14, Point::new(10.0, 10.0));
        self.point2(15, Point::new(10.0, 10.0));
        // The view direction: straight down the z axis.
        self.point2(16, Point::ORIGIN);
        self.pair(36, "1.0");
        self.point(17, Point::ORIGIN);
        self.mm(40, 620.0);
        self.mm(41, 1.42);
        self.mm(42, 50.0);
        for code in [43, 44, 50, 51] {
            self.pair(code, "0.0");
        }
        for (code, value) in [(71, 0), (72, 1000), (73, 1), (74, 3), (75, 0), (76, 0), (77, 0), (78, 0)] {
            self.pair(code, value);
        }
    }

    /// A linetype of dashes (positive) and gaps (`pattern` alternates them, mm).
    pub(super) fn linetype(&mut self, handle: u32, name: &str, description: &str, pattern: &[f64]) {
        self.record("LTYPE", handle, h::LTYPE_TABLE, "AcDbLinetypeTableRecord", name);
        self.pair(3, description);
        self.pair(72, 65);
        self.pair(73, pattern.len());
        self.mm(40, pattern.iter().sum());
        for (i, &x) in pattern.iter().enumerate() {
            self.mm(49, if i % 2 == 0 { x } else { -x });
            if self.r2000 {
                self.pair(74, 0);
            }
        }
    }

    pub(super) fn layer(&mut self, handle: u32, name: &str, kind: Kind) {
        self.record("LAYER", handle, h::LAYER_TABLE, "AcDbLayerTableRecord", name);
        self.pair(62, kind.colour());
        self.pair(6, kind.linetype());
        if self.r2000 {
            self.pair(370, kind.lineweight());
            self.hnd(390, h::PLOTSTYLE_NORMAL);
        }
    }

    pub(super) fn style(&mut self, handle: u32, name: &str, font: &str) {
        self.record("STYLE", handle, h::STYLE_TABLE, "AcDbTextStyleTableRecord", name);
        for (code, value) in [(40, "0.0"), (41, "1.0"), (50, "0.0")] {
            self.pair(code, value);
        }
        self.pair(71, 0);
        self.pair(42, "2.5");
        self.pair(3, font);
        self.pair(4, "");
    }

    pub(super) fn blocks(&mut self) {
        self.pair(0, "SECTION");
        self.pair(2, "BLOCKS");
        let spaces = if self.r2000 {
            [
                ("*Model_Space", h::MODEL_RECORD, h::MODEL_BLOCK, h::MODEL_ENDBLK),
                ("*Paper_Space", h::PAPER_RECORD, h::PAPER_BLOCK, h::PAPER_ENDBLK),
            ]
        } else {
            [("$MODEL_SPACE", 0, h::MODEL_BLOCK, h::MODEL_ENDBLK), ("$PAPER_SPACE", 0, h::PAPER_BLOCK, h::PAPER_ENDBLK)]
        };
        for (name, record, begin, end) in spaces {
            self.pair(0, "BLOCK");
            self.hnd(5, begin);
            self.owner(record);
            self.sub("AcDbEntity");
            self.pair(8, "0");
            self.sub("AcDbBlockBegin");
            self.pair(2, name);
            self.pair(70, 0);
            self.point(10, Point::ORIGIN);
            self.pair(3, name);
            self.pair(1, "");
            self.pair(0, "ENDBLK");
            self.hnd(5, end);
            self.owner(record);
            self.sub("AcDbEntity");
            self.pair(8, "0");
            self.sub("AcDbBlockEnd");
        }
        self.pair(0, "ENDSEC");
    }
    pub(super) fn dictionary(&mut self, kind: &str, handle: u32, owner: u32, entries: &[(&str, u32)]) {
        self.pair(0, kind);
        self.hnd(5, handle);
        self.hnd(330, owner);
        self.pair(100, "AcDbDictionary");
        self.pair(281, 1);
        for &(name, entry) in entries {
            self.pair(3, name);
            self.hnd(350, entry);
        }
    }

    pub(super) fn objects(&mut self, scene: &Scene) {
        self.pair(0, "SECTION");
        self.pair(2, "OBJECTS");
        self.dictionary(
            "DICTIONARY",
            h::ROOT_DICT,
            0,
            &[
                ("ACAD_GROUP", h::GROUP_DICT),
                ("ACAD_LAYOUT", h::LAYOUT_DICT),
                ("ACAD_MLINESTYLE", h::MLINESTYLE_DICT),
                ("ACAD_PLOTSTYLENAME", h::PLOTSTYLE_DICT),
            ],
        );
        self.dictionary("DICTIONARY", h::GROUP_DICT, h::ROOT_DICT, &[]);
        self.dictionary(
            "DICTIONARY",
            h::LAYOUT_DICT,
            h::ROOT_DICT,
            &[("Model", h::MODEL_LAYOUT), ("Layout1", h::PAPER_LAYOUT)],
        );
        self.dictionary("DICTIONARY", h::MLINESTYLE_DICT, h::ROOT_DICT, &[("Standard", h::MLINESTYLE_STANDARD)]);
        self.dictionary("ACDBDICTIONARYWDFLT", h::PLOTSTYLE_DICT, h::ROOT_DICT, &[("Normal", h::PLOTSTYLE_NORMAL)]);
        self.pair(100, "AcDbDictionaryWithDefault");
        self.hnd(340, h::PLOTSTYLE_NORMAL);
        self.pair(0, "ACDBPLACEHOLDER");
        self.hnd(5, h::PLOTSTYLE_NORMAL);
        self.hnd(330, h::PLOTSTYLE_DICT);
        let size = Point::new(scene.width, scene.height);
        self.layout(h::MODEL_LAYOUT, "Model", 0, h::MODEL_RECORD, size);
        self.layout(h::PAPER_LAYOUT, "Layout1", 1, h::PAPER_RECORD, size);
        self.pair(0, "MLINESTYLE");
        self.hnd(5, h::MLINESTYLE_STANDARD);
        self.hnd(330, h::MLINESTYLE_DICT);
        self.pair(100, "AcDbMlineStyle");
        self.pair(2, "Standard");
        self.pair(70, 0);
        self.pair(3, "");
        self.pair(62, 256);
        self.pair(51, "90.0");
        self.pair(52, "90.0");
        self.pair(71, 2);
        for offset in ["0.5", "-0.5"] {
            self.pair(49, offset);
            self.pair(62, 256);
            self.pair(6, "BYLAYER");
        }
        self.pair(0, "ENDSEC");
    }

    /// A layout on an A1 sheet in millimetres.
    pub(super) fn layout(&mut self, handle: u32, name: &str, order: i32, record: u32, size: Point) {
        self.pair(0, "LAYOUT");
        self.hnd(5, handle);
        self.hnd(330, h::LAYOUT_DICT);
        self.pair(100, "AcDbPlotSettings");
        self.pair(1, "");
        self.pair(4, "ISO_A1_(841.00_x_594.00_MM)");
        self.pair(6, "");
        for code in [40, 41, 42, 43] {
            self.pair(code, "0.0");
        }
        self.mm(44, size.x);
        self.mm(45, size.y);
        for code in [46, 47, 48, 49, 140, 141] {
            self.pair(code, "0.0");
        }
        self.pair(142, "1.0");
        self.pair(143, "1.0");
        // 70: plot flags (1024 for the model: "model type"); 72: paper units mm; 74: plot
        // type 5 (layout); 75: standard scale 16 (1:1).
        self.pair(70, if order == 0 { 1024 } else { 0 });
        self.pair(72, 1);
        self.pair(73, 0);
        self.pair(74, 5);
        self.pair(7, "");
        self.pair(75, 16);
        self.pair(76, 0);
        self.pair(77, 2);
        self.pair(78, 300);
        self.pair(147, "1.0");
        self.pair(148, "0.0");
        self.pair(149, "0.0");
        self.pair(100, "AcDbLayout");
        self.pair(1, name);
        self.pair(70, 1);
        self.pair(71, order);
        self.point2(10, Point::ORIGIN);
        self.point2(11, size);
        self.point(12, Point::ORIGIN);
        self.point(14, Point::ORIGIN);
        self.point(15, size);
        self.pair(146, "0.0");
        self.point(13, Point::ORIGIN);
        self.point(16, Point::new(1.0, 0.0));
        self.point(17, Point::new(0.0, 1.0));
        self.pair(76, 1);
        self.hnd(330, record);
    }
}
