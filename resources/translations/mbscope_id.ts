<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="id_ID">
<context>
    <name>QGnomeTheme</name>
    <message>
        <location filename="../../ui/shell/translationloader.cpp" line="+35"/>
        <source>&amp;OK</source>
        <translation>&amp;OK</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Save</source>
        <translation>&amp;Simpan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Cancel</source>
        <translation>&amp;Batal</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Close</source>
        <translation>&amp;Tutup</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Close without Saving</source>
        <translation>Tutup tanpa Menyimpan</translation>
    </message>
</context>
<context>
    <name>QLineEdit</name>
    <message>
        <location line="+1"/>
        <source>&amp;Undo</source>
        <translation>&amp;Urungkan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Redo</source>
        <translation>&amp;Ulangi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cu&amp;t</source>
        <translation>&amp;Potong</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Copy</source>
        <translation>&amp;Salin</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Paste</source>
        <translation>&amp;Tempel</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Delete</source>
        <translation>Hapus</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Select All</source>
        <translation>Pilih Semua</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <location filename="../../app/gui.cpp" line="+349"/>
        <source>Session not opened</source>
        <translation>Sesi tidak dibuka</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 was not opened:
%2</source>
        <translation>%1 tidak dibuka:
%2</translation>
    </message>
</context>
<context>
    <name>QPlatformTheme</name>
    <message>
        <location filename="../../ui/shell/translationloader.cpp" line="-29"/>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save</source>
        <translation>Simpan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save All</source>
        <translation>Simpan Semua</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open</source>
        <translation>Buka</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Yes</source>
        <translation>&amp;Ya</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Yes to &amp;All</source>
        <translation>Ya untuk &amp;Semua</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;No</source>
        <translation>&amp;Tidak</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>N&amp;o to All</source>
        <translation>T&amp;idak untuk Semua</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Abort</source>
        <translation>Batalkan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Retry</source>
        <translation>Coba Lagi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ignore</source>
        <translation>Abaikan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Close</source>
        <translation>Tutup</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancel</source>
        <translation>Batal</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Discard</source>
        <translation>Buang</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Help</source>
        <translation>Bantuan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Apply</source>
        <translation>Terapkan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reset</source>
        <translation>Atur Ulang</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Restore Defaults</source>
        <translation>Kembalikan Bawaan</translation>
    </message>
</context>
<context>
    <name>QWidgetTextControl</name>
    <message>
        <location line="+13"/>
        <source>&amp;Undo</source>
        <translation>&amp;Urungkan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Redo</source>
        <translation>&amp;Ulangi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cu&amp;t</source>
        <translation>&amp;Potong</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Copy</source>
        <translation>&amp;Salin</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Copy &amp;Link Location</source>
        <translation>Salin Lokasi &amp;Tautan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Paste</source>
        <translation>&amp;Tempel</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Delete</source>
        <translation>Hapus</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Select All</source>
        <translation>Pilih Semua</translation>
    </message>
</context>
<context>
    <name>ScanForm</name>
    <message>
        <location filename="../../ui/discovery/scanform.cpp" line="+33"/>
        <source>01 Read Coils</source>
        <translation>01 Baca Coil</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>02 Read Discrete Inputs</source>
        <translation>02 Baca Input Diskret</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>03 Read Holding Registers</source>
        <translation>03 Baca Register Holding</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>04 Read Input Registers</source>
        <translation>04 Baca Register Input</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>%1, about %2 left</source>
        <translation>%1, sekitar %2 lagi</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 s</source>
        <translation>%1 dtk</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 min %2 s</source>
        <translation>%1 mnt %2 dtk</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Cannot read %1: %2</source>
        <translation>Tidak dapat membaca %1: %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 is not a profile the simulator loads, so nothing was recorded in it: %2</source>
        <translation>%1 bukan profil yang dapat dimuat simulator, jadi tidak ada yang dicatat di dalamnya: %2</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Cannot record it in %1: %2</source>
        <translation>Tidak dapat mencatatnya di %1: %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Cannot save %1: %2</source>
        <translation>Tidak dapat menyimpan %1: %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Recorded in %1: %2.</source>
        <translation>Dicatat di %1: %2.</translation>
    </message>
</context>
<context>
    <name>TrafficSaver</name>
    <message>
        <location filename="../../ui/traffic/trafficsaver.cpp" line="+68"/>
        <source>Traffic journal (*.mbscope.journal)</source>
        <translation>Jurnal lalu lintas (*.mbscope.journal)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Wireshark capture, pcapng (*.pcapng)</source>
        <translation>Tangkapan Wireshark, pcapng (*.pcapng)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Wireshark capture, pcap (*.pcap)</source>
        <translation>Tangkapan Wireshark, pcap (*.pcap)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>CSV, a row per transaction (*.csv)</source>
        <translation>CSV, satu baris per transaksi (*.csv)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>JSON lines, an object per transaction (*.jsonl)</source>
        <translation>Baris JSON, satu objek per transaksi (*.jsonl)</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Traffic not saved to %1: %2</source>
        <translation>Lalu lintas tidak disimpan ke %1: %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 frame(s) saved to %2</source>
        <translation>%1 frame disimpan ke %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 frame(s) saved to %2 as %3 packet(s)</source>
        <translation>%1 frame disimpan ke %2 sebagai %3 paket</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 frame(s) saved to %2 as %3 transaction(s)</source>
        <translation>%1 frame disimpan ke %2 sebagai %3 transaksi</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>. Wireshark decodes the RTU frames with: %1</source>
        <translation>. Wireshark mendekode frame RTU dengan: %1</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>no room for a temporary journal: %1</source>
        <translation>tidak ada tempat untuk jurnal sementara: %1</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>cannot move %1 to %2</source>
        <translation>tidak dapat memindahkan %1 ke %2</translation>
    </message>
</context>
<context>
    <name>mbscope::AddressField</name>
    <message>
        <location filename="../../ui/compose/addressfield.cpp" line="+26"/>
        <source>Decimal (0-based)</source>
        <translation>Desimal (mulai 0)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Hex (0-based)</source>
        <translation>Hex (mulai 0)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Modicon (1-based)</source>
        <translation>Modicon (mulai 1)</translation>
    </message>
    <message>
        <location line="+114"/>
        <source>type an address</source>
        <translation>ketik alamat</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&apos;%1&apos; is not a decimal number (switch the notation to Hex for 0x... addresses)</source>
        <translation>&apos;%1&apos; bukan bilangan desimal (ganti notasi ke Hex untuk alamat 0x...)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>address %1 is out of range: PDU addresses are 0-65535</source>
        <translation>alamat %1 di luar rentang: alamat PDU adalah 0-65535</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>&apos;%1&apos; is not a hex number (0x0079 or 79)</source>
        <translation>&apos;%1&apos; bukan bilangan hex (0x0079 atau 79)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>address 0x%1 is out of range: PDU addresses are 0x0000-0xFFFF</source>
        <translation>alamat 0x%1 di luar rentang: alamat PDU adalah 0x0000-0xFFFF</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 is a reference to %2, but this function addresses %3 (%4xxxx)</source>
        <translation>%1 adalah referensi ke %2, tetapi fungsi ini mengalamati %3 (%4xxxx)</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>%1 looks like a Modicon reference; its PDU address is %2 (0x%3): choose Modicon (1-based) to type it as one</source>
        <translation>%1 tampak seperti referensi Modicon; alamat PDU-nya %2 (0x%3): pilih Modicon (mulai 1) untuk mengetiknya sebagai referensi</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>PDU address %1 (0x%2), 0-based</source>
        <translation>Alamat PDU %1 (0x%2), mulai 0</translation>
    </message>
</context>
<context>
    <name>mbscope::ConformanceDialog</name>
    <message>
        <location filename="../../ui/conformance/conformancedialog.cpp" line="+37"/>
        <source> ms</source>
        <translation> md</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Run</source>
        <translation>&amp;Jalankan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sto&amp;p</source>
        <translation>&amp;Hentikan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Save report…</source>
        <translation>&amp;Simpan laporan…</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Conformance</source>
        <translation>Kesesuaian</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The link of the slave under test. The battery opens a connection of its own.</source>
        <translation>Link slave yang diuji. Rangkaian uji membuka sambungannya sendiri.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The unit id under test, 1-247.</source>
        <translation>Id unit yang diuji, 1-247.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>How long each request waits for its answer.</source>
        <translation>Berapa lama setiap permintaan menunggu jawabannya.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>none: what the device supports is read from its answers</source>
        <translation>tidak ada: apa yang didukung perangkat dibaca dari jawabannya</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A device profile (shipped name or JSON file) that declares what the device promises: its functions, and its tables&apos; readable and missing addresses.</source>
        <translation>Profil perangkat (nama bawaan atau berkas JSON) yang menyatakan janji perangkat: fungsinya, serta alamat tabel yang dapat dibaca dan yang tidak ada.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>none: the battery only reads</source>
        <translation>tidak ada: rangkaian uji hanya membaca</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Addresses the write checks may use, each value found is put back: holding:10-13, coils:10-17. Empty: nothing is written.</source>
        <translation>Alamat yang boleh dipakai pemeriksaan tulis, setiap nilai yang ditemukan dikembalikan: holding:10-13, coils:10-17. Kosong: tidak ada yang ditulis.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>every check</source>
        <translation>semua pemeriksaan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Run only the checks whose id starts with one of these, comma-separated: read.03, mbap</source>
        <translation>Jalankan hanya pemeriksaan yang id-nya diawali salah satu dari ini, dipisah koma: read.03, mbap</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Save the scorecard as an HTML page, a PDF, JSON or JUnit XML</source>
        <translation>Simpan kartu skor sebagai halaman HTML, PDF, JSON atau JUnit XML</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>&amp;Target:</source>
        <translation>Ta&amp;rget:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>timeout</source>
        <translation>batas waktu</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Unit:</source>
        <translation>&amp;Unit:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Profile:</source>
        <translation>&amp;Profil:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Writable:</source>
        <translation>Dapat &amp;ditulis:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Only:</source>
        <translation>Hany&amp;a:</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Close</source>
        <translation>&amp;Tutup</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Reads only, unless Writable names addresses. A failure says what was sent, what came back and what the clause requires.</source>
        <translation>Hanya membaca, kecuali Dapat ditulis menyebut alamat. Kegagalan menyebut apa yang dikirim, apa yang kembali, dan apa yang diwajibkan pasalnya.</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Type the link of the slave under test.</source>
        <translation>Ketik link slave yang diuji.</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Writable: %1</source>
        <translation>Dapat ditulis: %1</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Only: %1 selects no check.</source>
        <translation>Hanya: %1 tidak memilih pemeriksaan apa pun.</translation>
    </message>
    <message>
        <location line="+7"/>
        <location line="+5"/>
        <source>Profile %1: %2</source>
        <translation>Profil %1: %2</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Running: reads only…</source>
        <translation>Berjalan: hanya membaca…</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Running: writes allowed on %1…</source>
        <translation>Berjalan: boleh menulis pada %1…</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>Not tested: %1</source>
        <translation>Tidak diuji: %1</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Stopping after the check that runs now…</source>
        <translation>Berhenti setelah pemeriksaan yang sedang berjalan…</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>There is no scorecard to save: run the battery first.</source>
        <translation>Belum ada kartu skor untuk disimpan: jalankan rangkaian uji dulu.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1: name the file .html, .pdf, .json or .xml (JUnit) to say which report to save.</source>
        <translation>%1: beri nama berkas .html, .pdf, .json atau .xml (JUnit) untuk menyebut laporan mana yang disimpan.</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>HTML page (*.html);;PDF (*.pdf);;JSON (*.json);;JUnit XML (*.xml)</source>
        <translation>Halaman HTML (*.html);;PDF (*.pdf);;JSON (*.json);;JUnit XML (*.xml)</translation>
    </message>
    <message>
        <location line="-11"/>
        <location line="+3"/>
        <source>cannot write %1: %2</source>
        <translation>tidak dapat menulis %1: %2</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Save the scorecard</source>
        <translation>Simpan kartu skor</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Saved %1.</source>
        <translation>Disimpan %1.</translation>
    </message>
</context>
<context>
    <name>mbscope::ConformanceResultModel</name>
    <message>
        <location filename="../../ui/conformance/conformanceresultmodel.cpp" line="+71"/>
        <source>(none)</source>
        <translation>(tidak ada)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1, %2</source>
        <translation>%1, %2</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Verdict</source>
        <translation>Hasil</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Check</source>
        <translation>Pemeriksaan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Clause</source>
        <translation>Pasal</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Why</source>
        <translation>Alasan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Request</source>
        <translation>Permintaan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Answer</source>
        <translation>Jawaban</translation>
    </message>
</context>
<context>
    <name>mbscope::ConnectionBar</name>
    <message>
        <location filename="../../ui/link/connectionbar.cpp" line="+34"/>
        <source>Modbus TCP</source>
        <translation>Modbus TCP</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Modbus TCP Security (TLS)</source>
        <translation>Modbus TCP Security (TLS)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RTU over TCP</source>
        <translation>RTU lewat TCP</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ASCII over TCP</source>
        <translation>ASCII lewat TCP</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Modbus UDP</source>
        <translation>Modbus UDP</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RTU over UDP</source>
        <translation>RTU lewat UDP</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RTU (serial)</source>
        <translation>RTU (serial)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ASCII (serial)</source>
        <translation>ASCII (serial)</translation>
    </message>
    <message>
        <location line="+48"/>
        <source>host name or IP address</source>
        <translation>nama host atau alamat IP</translation>
    </message>
    <message>
        <location line="+54"/>
        <source>P&amp;ort:</source>
        <translation>P&amp;ort:</translation>
    </message>
    <message>
        <location line="-29"/>
        <source>/dev/ttyUSB0</source>
        <translation>/dev/ttyUSB0</translation>
    </message>
    <message>
        <location line="-13"/>
        <source>H&amp;ost:</source>
        <translation>H&amp;ost:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Port:</source>
        <translation>Port:</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Refresh</source>
        <translation>Segarkan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Look for serial ports again (after plugging in an adapter)</source>
        <translation>Cari port serial lagi (setelah adaptor dicolokkan)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Even</source>
        <translation>Genap</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Odd</source>
        <translation>Ganjil</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>None</source>
        <translation>Tidak ada</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>&amp;Baud:</source>
        <translation>&amp;Baud:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Pa&amp;rity:</source>
        <translation>Pa&amp;ritas:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Data:</source>
        <translation>Bit &amp;data:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Stop:</source>
        <translation>Bit &amp;stop:</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Unit (slave) id put into built and completed requests; 0 is a broadcast on serial lines</source>
        <translation>ID unit (slave) yang dimasukkan ke permintaan yang dibuat dan dilengkapi; 0 adalah broadcast di jalur serial</translation>
    </message>
    <message>
        <location line="+6"/>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>How long to wait for an answer before the request counts as timed out</source>
        <translation>Berapa lama menunggu jawaban sebelum permintaan dianggap habis waktu</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Device &amp;pace…</source>
        <translation>&amp;Tempo perangkat…</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>Targets connected to before, and the device&apos;s pace</source>
        <translation>Target yang pernah disambungkan, dan tempo perangkat</translation>
    </message>
    <message>
        <location line="+138"/>
        <source>Options of this target that no field here shows, used on Connect: %1. They came with the target (a recent target, a session or the command line) or from Device pace…; choose another link type to drop them.</source>
        <translation>Opsi target ini yang tidak ditampilkan kolom mana pun, dipakai saat Sambung: %1. Opsi ini datang bersama target (target terbaru, sesi, atau baris perintah) atau dari Tempo perangkat…; pilih jenis tautan lain untuk membuangnya.</translation>
    </message>
    <message>
        <location line="-177"/>
        <source>The device&apos;s pace: a gap between requests, a wait after connecting, a new connection for each request (by hand or from a device profile)</source>
        <translation>Tempo perangkat: jeda antar permintaan, tunggu setelah tersambung, sambungan baru untuk setiap permintaan (manual atau dari profil perangkat)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>L&amp;isten</source>
        <translation>Si&amp;mak</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Monitor a bus another master drives: every exchange on the line is shown, paired and measured, and nothing is ever sent (serial links, RTU or ASCII over TCP)</source>
        <translation>Pantau bus yang dikendalikan master lain: setiap pertukaran di jalur ditampilkan, dipasangkan, dan diukur, dan tidak ada yang pernah dikirim (tautan serial, RTU atau ASCII lewat TCP)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Tap</source>
        <translation>Sadap</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Put the window between masters and this device: masters connect to the Tap row&apos;s URLs, each request goes on to the target above (or a route&apos;s), the answer back; both legs are shown, decoded and recorded (mbscope tap in the window)</source>
        <translation>Tempatkan jendela di antara master dan perangkat ini: master tersambung ke URL di baris Sadap, setiap permintaan diteruskan ke target di atas (atau target sebuah rute), jawabannya kembali; kedua sisi ditampilkan, didekode, dan direkam (mbscope tap di jendela)</translation>
    </message>
    <message>
        <location line="+19"/>
        <location line="+314"/>
        <source>&amp;Connect</source>
        <translation>Sa&amp;mbungkan</translation>
    </message>
    <message>
        <location line="-311"/>
        <source>Disconnect</source>
        <translation>Putuskan</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Recent</source>
        <translation>Terakhir</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>&amp;Link:</source>
        <translation>&amp;Link:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Unit:</source>
        <translation>&amp;Unit:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Ti&amp;meout:</source>
        <translation>Batas &amp;waktu:</translation>
    </message>
    <message>
        <location line="+159"/>
        <source>No serial port found: plug in the adapter and press Refresh, or type the device path</source>
        <translation>Tidak ada port serial: colokkan adaptor lalu tekan Segarkan, atau ketik path perangkatnya</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Serial ports found: %1</source>
        <translation>Port serial yang ditemukan: %1</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Choose a serial port: none was found. Plug in the adapter and press Refresh, or type its path (/dev/ttyUSB0).</source>
        <translation>Pilih port serial: tidak ada yang ditemukan. Colokkan adaptor lalu tekan Segarkan, atau ketik path-nya (/dev/ttyUSB0).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Choose a serial port from the list (or type its path, e.g. /dev/ttyUSB0).</source>
        <translation>Pilih port serial dari daftar (atau ketik path-nya, mis. /dev/ttyUSB0).</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Baud rate &apos;%1&apos; is not a number: choose one from the list (9600, 19200...).</source>
        <translation>Baud rate &apos;%1&apos; bukan angka: pilih dari daftar (9600, 19200...).</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>RTU needs 8 data bits (Serial Line V1.02, 2.5.1): set Data to 8.</source>
        <translation>RTU memerlukan 8 bit data (Serial Line V1.02, 2.5.1): atur Bit data ke 8.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Type the device&apos;s host name or IP address (for example 192.168.127.254).</source>
        <translation>Ketik nama host atau alamat IP perangkat (misalnya 192.168.127.254).</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Host &apos;%1&apos; is not a host name or IP address: type only the address, the port goes in Port.</source>
        <translation>Host &apos;%1&apos; bukan nama host atau alamat IP: ketik alamatnya saja, port diisi di Port.</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>This target cannot be used: %1</source>
        <translation>Target ini tidak bisa dipakai: %1</translation>
    </message>
    <message>
        <location line="+61"/>
        <source>Dis&amp;connect</source>
        <translation>Putus&amp;kan</translation>
    </message>
    <message>
        <location line="+49"/>
        <source>The link failed: %1. Check that the device is powered and reachable at this address, then send again (the link reopens), or press Disconnect to change the target.</source>
        <translation>Link gagal: %1. Pastikan perangkat menyala dan dapat dijangkau di alamat ini, lalu kirim lagi (link dibuka kembali), atau tekan Putuskan untuk mengganti target.</translation>
    </message>
    <message>
        <location line="+66"/>
        <source>The recent target &apos;%1&apos; cannot be read: %2</source>
        <translation>Target terakhir &apos;%1&apos; tidak dapat dibaca: %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>(no recent targets yet)</source>
        <translation>(belum ada target terakhir)</translation>
    </message>
</context>
<context>
    <name>mbscope::CsvExportAction</name>
    <message>
        <location filename="../../ui/common/csvexportaction.cpp" line="+13"/>
        <source>Export table as &amp;CSV…</source>
        <translation>Ekspor tabel sebagai &amp;CSV…</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Save the table as comma-separated values</source>
        <translation>Simpan tabel sebagai nilai yang dipisahkan koma</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Export table</source>
        <translation>Ekspor tabel</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CSV file (*.csv)</source>
        <translation>Berkas CSV (*.csv)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Table saved to %1</source>
        <translation>Tabel disimpan ke %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Table not saved: %1</source>
        <translation>Tabel tidak disimpan: %1</translation>
    </message>
</context>
<context>
    <name>mbscope::DecodePanel</name>
    <message>
        <location filename="../../ui/decode/decodepanel.cpp" line="+58"/>
        <source>Type or paste a frame as hex: 01 03 00 79 00 16 15 DD</source>
        <translation>Ketik atau tempel frame sebagai hex: 01 03 00 79 00 16 15 DD</translation>
    </message>
    <message>
        <location line="+7"/>
        <location line="+9"/>
        <source>Auto-detect</source>
        <translation>Deteksi otomatis</translation>
    </message>
    <message>
        <location line="-8"/>
        <source>RTU</source>
        <translation>RTU</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ASCII</source>
        <translation>ASCII</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>TCP (MBAP)</source>
        <translation>TCP (MBAP)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>UDP (MBAP)</source>
        <translation>UDP (MBAP)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PDU only</source>
        <translation>Hanya PDU</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Request</source>
        <translation>Permintaan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Response</source>
        <translation>Respons</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>optional: the request this response answers</source>
        <translation>opsional: permintaan yang dijawab respons ini</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>With the matching request, a response&apos;s byte count, echoed values and transaction id are checked against what was asked</source>
        <translation>Dengan permintaan yang cocok, jumlah byte, nilai yang dikembalikan dan ID transaksi respons diperiksa terhadap yang diminta</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Frame:</source>
        <translation>Frame:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Framing:</source>
        <translation>Framing:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Direction:</source>
        <translation>Arah:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Matching re&amp;quest:</source>
        <translation>Permintaan yang &amp;cocok:</translation>
    </message>
    <message>
        <location line="+113"/>
        <source>Frame</source>
        <translation>Frame</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Matching request</source>
        <translation>Permintaan yang cocok</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Valid:</source>
        <translation>Valid:</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Invalid:</source>
        <translation>Tidak valid:</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+1"/>
        <source>as chosen</source>
        <translation>sesuai pilihan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Framing %1: %2. Direction %3: %4.</source>
        <translation>Framing %1: %2. Arah %3: %4.</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Type or paste a frame as hex; the fields appear as you type.</source>
        <translation>Ketik atau tempel frame sebagai hex; field-nya muncul sambil Anda mengetik.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>(the tree shows the last input that could be read)</source>
        <translation>(pohon menampilkan input terakhir yang dapat dibaca)</translation>
    </message>
</context>
<context>
    <name>mbscope::DecodeView</name>
    <message>
        <location filename="../../ui/decode/decodeview.cpp" line="+41"/>
        <source>Copy</source>
        <translation>Salin</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Copy both frames: as text (as `mbscope decode` prints them), as JSON or as hex</source>
        <translation>Salin kedua frame: sebagai teks (seperti dicetak `mbscope decode`), sebagai JSON atau sebagai hex</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Copy as &amp;text</source>
        <translation>Salin sebagai &amp;teks</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Copy as &amp;JSON</source>
        <translation>Salin sebagai &amp;JSON</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Copy as &amp;hex</source>
        <translation>Salin sebagai &amp;hex</translation>
    </message>
    <message>
        <location line="+62"/>
        <source>No request: this frame answers none that was sent (%1)</source>
        <translation>Tanpa permintaan: frame ini tidak menjawab permintaan yang dikirim (%1)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No request</source>
        <translation>Tanpa permintaan</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>No answer yet</source>
        <translation>Belum ada jawaban</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Broadcast: no answer is expected</source>
        <translation>Broadcast: tidak ada jawaban yang diharapkan</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No answer: %1</source>
        <translation>Tidak ada jawaban: %1</translation>
    </message>
    <message>
        <location line="+23"/>
        <location line="+13"/>
        <source>Request</source>
        <translation>Permintaan</translation>
    </message>
    <message>
        <location line="-12"/>
        <location line="+13"/>
        <source>Response</source>
        <translation>Respons</translation>
    </message>
    <message>
        <location line="-12"/>
        <source>Select a frame in the traffic list, or send a request</source>
        <translation>Pilih frame di daftar lalu lintas, atau kirim permintaan</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No exchange selected</source>
        <translation>Tidak ada pertukaran yang dipilih</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>after %1</source>
        <translation>setelah %1</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>latency %1 to the answer&apos;s last byte</source>
        <translation>latensi %1 sampai byte terakhir jawaban</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>latency %1 to the answer&apos;s first byte</source>
        <translation>latensi %1 sampai byte pertama jawaban</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Latency of the transaction, as the Analysis dock and the poll&apos;s figures count it: from the request sent (on a serial line, its last byte on the line) to the answer&apos;s last byte. The traffic list&apos;s Latency column measures to the answer&apos;s first byte.</source>
        <translation>Latensi transaksi, seperti dihitung dok Analisis dan angka polling: dari permintaan terkirim (pada jalur serial, byte terakhirnya di jalur) sampai byte terakhir jawaban. Kolom Latensi di daftar lalu lintas mengukur sampai byte pertama jawaban.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Latency as the traffic list shows it: from the request&apos;s write to the answer&apos;s first byte. The Analysis dock measures to the answer&apos;s last byte.</source>
        <translation>Latensi seperti ditampilkan daftar lalu lintas: dari penulisan permintaan sampai byte pertama jawaban. Dok Analisis mengukur sampai byte terakhir jawaban.</translation>
    </message>
    <message>
        <location line="-9"/>
        <source>transaction %1</source>
        <translation>transaksi %1</translation>
    </message>
</context>
<context>
    <name>mbscope::DissectionSummary</name>
    <message>
        <location filename="../../ui/decode/dissectionsummary.cpp" line="+17"/>
        <source>Frame</source>
        <translation>Frame</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1 request</source>
        <translation>permintaan %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 response</source>
        <translation>respons %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1, unit %2</source>
        <translation>%1, unit %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: no function code</source>
        <translation>%1: tanpa kode fungsi</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: %2 exception</source>
        <translation>%1: pengecualian %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1, %2 from address %3</source>
        <translation>%1, %2 mulai alamat %3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1, address %2</source>
        <translation>%1, alamat %2</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1, address %2 = %3</source>
        <translation>%1, alamat %2 = %3</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1, 1 register value</source>
        <translation>%1, 1 nilai register</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1, %2 register values</source>
        <translation>%1, %2 nilai register</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1, 1 bit</source>
        <translation>%1, 1 bit</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1, %2 bits</source>
        <translation>%1, %2 bit</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>[1 error]</source>
        <translation>[1 error]</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>[%1 errors]</source>
        <translation>[%1 error]</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>[1 warning]</source>
        <translation>[1 peringatan]</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>[%1 warnings]</source>
        <translation>[%1 peringatan]</translation>
    </message>
</context>
<context>
    <name>mbscope::EmbeddedSimulator</name>
    <message>
        <location filename="../../ui/sim/embeddedsimulator.cpp" line="+25"/>
        <source>The simulator&apos;s profile &apos;%1&apos; cannot be loaded: %2</source>
        <translation>Profil simulator &apos;%1&apos; tidak dapat dimuat: %2</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The simulator&apos;s profile &apos;%1&apos; has no usable unit: %2</source>
        <translation>Profil simulator &apos;%1&apos; tidak punya unit yang bisa dipakai: %2</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Port %1 is in use by another program, so the simulator listens on port %2 instead.</source>
        <translation>Port %1 dipakai program lain, jadi simulator mendengarkan di port %2.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The simulator cannot listen on %1: %2</source>
        <translation>Simulator tidak dapat mendengarkan di %1: %2</translation>
    </message>
</context>
<context>
    <name>mbscope::ExportMapDialog</name>
    <message>
        <location filename="../../ui/discovery/exportmapdialog.cpp" line="+63"/>
        <source>no usable answer</source>
        <translation>tidak ada jawaban yang dapat dipakai</translation>
    </message>
    <message>
        <location line="+13"/>
        <source> ms</source>
        <translation> md</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Export</source>
        <translation>&amp;Ekspor</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Export map</source>
        <translation>Ekspor peta</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>a shipped profile&apos;s name or a JSON file</source>
        <translation>nama profil bawaan atau berkas JSON</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the profile&apos;s first endpoint the format takes</source>
        <translation>titik ujung pertama profil yang diterima format ini</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Where the tool will reach the device: tcp://host:port, rtu-tcp://..., rtu:///dev/ttyUSB0?baud=...</source>
        <translation>Tempat alat itu menjangkau perangkat: tcp://host:port, rtu-tcp://..., rtu:///dev/ttyUSB0?baud=...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>How often the tool polls.</source>
        <translation>Seberapa sering alat itu melakukan poll.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>empty: export without reading</source>
        <translation>kosong: ekspor tanpa membaca</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Read every value once from this target first and refuse the export when one is not finite or outside the min and max its entry declares.</source>
        <translation>Baca setiap nilai sekali dari tujuan ini lebih dulu dan tolak ekspor bila ada yang tidak hingga atau di luar min dan max yang dinyatakan entrinya.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&amp;Browse…</source>
        <translation>&amp;Telusuri…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ch&amp;oose…</source>
        <translation>Pilih &amp;berkas…</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&amp;Profile:</source>
        <translation>&amp;Profil:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Format:</source>
        <translation>&amp;Format:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>E&amp;ndpoint:</source>
        <translation>Titik &amp;ujung:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Poll &amp;interval:</source>
        <translation>&amp;Interval poll:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Verify from:</source>
        <translation>&amp;Verifikasi dari:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>O&amp;utput file:</source>
        <translation>Berkas &amp;keluaran:</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Writes the profile&apos;s register map for the tool that will poll the device (mbscope export-map).</source>
        <translation>Menulis peta register profil untuk alat yang akan melakukan poll ke perangkat (mbscope export-map).</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Which profile? Give a shipped profile&apos;s name or a JSON file.</source>
        <translation>Profil yang mana? Berikan nama profil bawaan atau berkas JSON.</translation>
    </message>
    <message numerus="yes">
        <location line="+16"/>
        <source>Nothing exported: %n value(s) cannot be read whole within the device&apos;s limits.maxQuantity: %1</source>
        <translation>
            <numerusform>Tidak ada yang diekspor: %n nilai tidak dapat dibaca utuh dalam limits.maxQuantity perangkat: %1</numerusform>
        </translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Endpoint: %1</source>
        <translation>Titik ujung: %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Endpoint %1: %2</source>
        <translation>Titik ujung %1: %2</translation>
    </message>
    <message>
        <location line="-21"/>
        <source>%1 has no table entries to export.</source>
        <translation>%1 tidak punya entri tabel untuk diekspor.</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Choose the output file.</source>
        <translation>Pilih berkas keluaran.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Verify from: %1</source>
        <translation>Verifikasi dari: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Reading every value once from %1…</source>
        <translation>Membaca setiap nilai sekali dari %1…</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>unit %1 %2 %3 (%4): %5</source>
        <translation>unit %1 %2 %3 (%4): %5</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Refused: %1 of %2 values read from %3 are not usable; nothing written.</source>
        <translation>Ditolak: %1 dari %2 nilai yang dibaca dari %3 tidak dapat dipakai; tidak ada yang ditulis.</translation>
    </message>
    <message numerus="yes">
        <location line="+5"/>
        <source>
and %n more</source>
        <translation>
            <numerusform>
dan %n lagi</numerusform>
        </translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Verified: %1 values read from %2 are finite and inside their ranges. </source>
        <translation>Terverifikasi: %1 nilai yang dibaca dari %2 hingga dan di dalam rentangnya. </translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Cannot write %1: %2</source>
        <translation>Tidak dapat menulis %1: %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Wrote %1 values in %2 blocks to %3 (%4).</source>
        <translation>Menulis %1 nilai dalam %2 blok ke %3 (%4).</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Device profile</source>
        <translation>Profil perangkat</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Device profiles (*.json)</source>
        <translation>Profil perangkat (*.json)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Export to</source>
        <translation>Ekspor ke</translation>
    </message>
</context>
<context>
    <name>mbscope::Field</name>
    <message>
        <location filename="../../core/protocol/aduascii.cpp" line="+71"/>
        <source>Start</source>
        <translation>Awal</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Frame text</source>
        <translation>Teks frame</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+14"/>
        <location filename="../../core/protocol/adumbap.cpp" line="+27"/>
        <location line="+42"/>
        <location filename="../../core/protocol/adurtu.cpp" line="+37"/>
        <location line="+7"/>
        <location line="+39"/>
        <location filename="../../core/protocol/pduchecks.cpp" line="+13"/>
        <source>Missing bytes</source>
        <translation>Byte yang hilang</translation>
    </message>
    <message>
        <location line="-10"/>
        <location filename="../../core/protocol/adumbap.cpp" line="-43"/>
        <location line="+27"/>
        <location filename="../../core/protocol/adurtu.cpp" line="-65"/>
        <source>Unit id</source>
        <translation>ID unit</translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../../core/protocol/adurtu.cpp" line="-1"/>
        <source>broadcast</source>
        <translation>broadcast</translation>
    </message>
    <message>
        <location line="+0"/>
        <location filename="../../core/protocol/adurtu.cpp" line="+0"/>
        <source>reserved address</source>
        <translation>alamat cadangan</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>LRC</source>
        <translation>LRC</translation>
    </message>
    <message>
        <location line="+0"/>
        <location filename="../../core/protocol/adurtu.cpp" line="+50"/>
        <source>(valid)</source>
        <translation>(valid)</translation>
    </message>
    <message>
        <location line="+0"/>
        <location filename="../../core/protocol/adurtu.cpp" line="+0"/>
        <source>(wrong)</source>
        <translation>(salah)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>End</source>
        <translation>Akhir</translation>
    </message>
    <message>
        <location filename="../../core/protocol/adumbap.cpp" line="-33"/>
        <location line="+13"/>
        <source>Transaction id</source>
        <translation>ID transaksi</translation>
    </message>
    <message>
        <location line="-11"/>
        <location line="+15"/>
        <source>Protocol id</source>
        <translation>ID protokol</translation>
    </message>
    <message>
        <location line="-13"/>
        <location line="+20"/>
        <source>Length</source>
        <translation>Panjang</translation>
    </message>
    <message>
        <location line="-6"/>
        <source>Modbus</source>
        <translation>Modbus</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>no unit behind a gateway (0xFF is the usual value for a direct TCP server)</source>
        <translation>tidak ada unit di balik gateway (0xFF adalah nilai yang lazim untuk server TCP langsung)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>direct or broadcast</source>
        <translation>langsung atau broadcast</translation>
    </message>
    <message>
        <location line="+8"/>
        <location filename="../../core/protocol/adurtu.cpp" line="+10"/>
        <source>Trailing bytes</source>
        <translation>Byte berlebih di akhir</translation>
    </message>
    <message>
        <location filename="../../core/protocol/adurtu.cpp" line="-10"/>
        <source>CRC</source>
        <translation>CRC</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>Extra bytes</source>
        <translation>Byte tambahan</translation>
    </message>
    <message>
        <location filename="../../core/protocol/diagnosticrules.cpp" line="+33"/>
        <location filename="../../core/protocol/pdudiagnostics.cpp" line="+44"/>
        <source>Return Query Data</source>
        <translation>Kembalikan Data Query</translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../../core/protocol/pdudiagnostics.cpp" line="+1"/>
        <source>Restart Communications Option</source>
        <translation>Opsi Restart Komunikasi</translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../../core/protocol/pdudiagnostics.cpp" line="+1"/>
        <source>Return Diagnostic Register</source>
        <translation>Kembalikan Register Diagnostik</translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../../core/protocol/pdudiagnostics.cpp" line="+1"/>
        <source>Change ASCII Input Delimiter</source>
        <translation>Ubah Delimiter Input ASCII</translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../../core/protocol/pdudiagnostics.cpp" line="+1"/>
        <source>Force Listen Only Mode</source>
        <translation>Paksa Mode Hanya-Dengar</translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../../core/protocol/pdudiagnostics.cpp" line="+1"/>
        <source>Clear Counters and Diagnostic Register</source>
        <translation>Kosongkan Penghitung dan Register Diagnostik</translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../../core/protocol/pdudiagnostics.cpp" line="+1"/>
        <source>Return Bus Message Count</source>
        <translation>Kembalikan Jumlah Pesan Bus</translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../../core/protocol/pdudiagnostics.cpp" line="+1"/>
        <source>Return Bus Communication Error Count</source>
        <translation>Kembalikan Jumlah Error Komunikasi Bus</translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../../core/protocol/pdudiagnostics.cpp" line="+1"/>
        <source>Return Bus Exception Error Count</source>
        <translation>Kembalikan Jumlah Error Pengecualian Bus</translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../../core/protocol/pdudiagnostics.cpp" line="+1"/>
        <source>Return Server Message Count</source>
        <translation>Kembalikan Jumlah Pesan Server</translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../../core/protocol/pdudiagnostics.cpp" line="+1"/>
        <source>Return Server No Response Count</source>
        <translation>Kembalikan Jumlah Tanpa Respons Server</translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../../core/protocol/pdudiagnostics.cpp" line="+1"/>
        <source>Return Server NAK Count</source>
        <translation>Kembalikan Jumlah NAK Server</translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../../core/protocol/pdudiagnostics.cpp" line="+1"/>
        <source>Return Server Busy Count</source>
        <translation>Kembalikan Jumlah Server Sibuk</translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../../core/protocol/pdudiagnostics.cpp" line="+1"/>
        <source>Return Bus Character Overrun Count</source>
        <translation>Kembalikan Jumlah Overrun Karakter Bus</translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../../core/protocol/pdudiagnostics.cpp" line="+1"/>
        <source>Clear Overrun Counter and Flag</source>
        <translation>Kosongkan Penghitung dan Flag Overrun</translation>
    </message>
    <message>
        <location filename="../../core/protocol/functionspec.h" line="+38"/>
        <source>Read Coils</source>
        <translation>Baca Coil</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Read Discrete Inputs</source>
        <translation>Baca Discrete Input</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>inputs</source>
        <translation>input</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Read Holding Registers</source>
        <translation>Baca Holding Register</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+1"/>
        <location line="+8"/>
        <location line="+5"/>
        <source>registers</source>
        <translation>register</translation>
    </message>
    <message>
        <location line="-13"/>
        <source>Read Input Registers</source>
        <translation>Baca Input Register</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write Single Coil</source>
        <translation>Tulis Satu Coil</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write Single Register</source>
        <translation>Tulis Satu Register</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Read Exception Status</source>
        <translation>Baca Status Pengecualian</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Diagnostics</source>
        <translation>Diagnostik</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Get Comm Event Counter</source>
        <translation>Ambil Penghitung Event Komunikasi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Get Comm Event Log</source>
        <translation>Ambil Log Event Komunikasi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write Multiple Coils</source>
        <translation>Tulis Banyak Coil</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write Multiple Registers</source>
        <translation>Tulis Banyak Register</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Report Server ID</source>
        <translation>Laporkan ID Server</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Read File Record</source>
        <translation>Baca Record File</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write File Record</source>
        <translation>Tulis Record File</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mask Write Register</source>
        <translation>Tulis Register dengan Mask</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Read/Write Multiple Registers</source>
        <translation>Baca/Tulis Banyak Register</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Read FIFO Queue</source>
        <translation>Baca Antrean FIFO</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Encapsulated Interface Transport</source>
        <translation>Transport Antarmuka Terenkapsulasi</translation>
    </message>
    <message>
        <location filename="../../core/protocol/functioncode.cpp" line="+34"/>
        <source>User-defined function</source>
        <translation>Fungsi buatan pengguna</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reserved function code</source>
        <translation>Kode fungsi cadangan</translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../../core/protocol/pdudissector.cpp" line="+74"/>
        <source>Exception response</source>
        <translation>Respons pengecualian</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Invalid function code</source>
        <translation>Kode fungsi tidak valid</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Unassigned function code</source>
        <translation>Kode fungsi yang belum ditetapkan</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Illegal Function</source>
        <translation>Fungsi Tidak Sah</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Illegal Data Address</source>
        <translation>Alamat Data Tidak Sah</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Illegal Data Value</source>
        <translation>Nilai Data Tidak Sah</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Server Device Failure</source>
        <translation>Kegagalan Perangkat Server</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Acknowledge</source>
        <translation>Diterima (Acknowledge)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Server Device Busy</source>
        <translation>Perangkat Server Sibuk</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Negative Acknowledge</source>
        <translation>Ditolak (Negative Acknowledge)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Memory Parity Error</source>
        <translation>Error Paritas Memori</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gateway Path Unavailable</source>
        <translation>Jalur Gateway Tidak Tersedia</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gateway Target Device Failed to Respond</source>
        <translation>Perangkat Tujuan Gateway Tidak Menjawab</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Unknown exception code</source>
        <translation>Kode pengecualian tidak dikenal</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Illegal Function: the function code is not supported by the device, or not allowed in its current state</source>
        <translation>Fungsi Tidak Sah: kode fungsi tidak didukung perangkat, atau tidak diizinkan dalam kondisinya saat ini</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Illegal Data Address: the address range is not available in the device</source>
        <translation>Alamat Data Tidak Sah: rentang alamat tidak tersedia di perangkat</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Illegal Data Value: a value in the request is not allowed, such as a quantity or length out of range</source>
        <translation>Nilai Data Tidak Sah: ada nilai dalam permintaan yang tidak diizinkan, misalnya jumlah atau panjang di luar rentang</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Server Device Failure: an unrecoverable error occurred while the device was performing the action</source>
        <translation>Kegagalan Perangkat Server: terjadi error yang tidak bisa dipulihkan saat perangkat menjalankan perintah</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Acknowledge: the device accepted the request but needs a long time to process it; poll it later</source>
        <translation>Diterima (Acknowledge): perangkat menerima permintaan tetapi butuh waktu lama untuk memprosesnya; tanyakan lagi nanti</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Server Device Busy: the device is processing a long-duration command; retry later</source>
        <translation>Perangkat Server Sibuk: perangkat sedang memproses perintah yang lama; coba lagi nanti</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Negative Acknowledge: the device cannot perform the program function (legacy Modicon code)</source>
        <translation>Ditolak (Negative Acknowledge): perangkat tidak dapat menjalankan fungsi program (kode Modicon lama)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Memory Parity Error: the device found a parity error in its extended file memory (function 20/21)</source>
        <translation>Error Paritas Memori: perangkat menemukan error paritas di memori file tambahannya (fungsi 20/21)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Gateway Path Unavailable: the gateway could not allocate a path to the target, it is misconfigured or overloaded</source>
        <translation>Jalur Gateway Tidak Tersedia: gateway tidak dapat menyediakan jalur ke tujuan, konfigurasinya salah atau bebannya berlebih</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Gateway Target Device Failed to Respond: the gateway got no answer from the target device</source>
        <translation>Perangkat Tujuan Gateway Tidak Menjawab: gateway tidak mendapat jawaban dari perangkat tujuan</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Unassigned exception code: 0x09 is not defined by the Modbus specification</source>
        <translation>Kode pengecualian yang belum ditetapkan: 0x09 tidak didefinisikan oleh spesifikasi Modbus</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Unknown exception code: the Modbus specification defines 0x01-0x08, 0x0A and 0x0B</source>
        <translation>Kode pengecualian tidak dikenal: spesifikasi Modbus mendefinisikan 0x01-0x08, 0x0A dan 0x0B</translation>
    </message>
    <message>
        <location filename="../../core/protocol/functionspec.h" line="-18"/>
        <location line="+10"/>
        <location filename="../../core/protocol/modiconreference.cpp" line="+197"/>
        <source>coils</source>
        <translation>coil</translation>
    </message>
    <message>
        <location filename="../../core/protocol/modiconreference.cpp" line="+1"/>
        <source>discrete inputs</source>
        <translation>discrete input</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>input registers</source>
        <translation>input register</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+2"/>
        <source>holding registers</source>
        <translation>holding register</translation>
    </message>
    <message>
        <location filename="../../core/protocol/pduchecks.cpp" line="+91"/>
        <source>Unexpected bytes</source>
        <translation>Byte tak terduga</translation>
    </message>
    <message>
        <location line="+38"/>
        <location filename="../../core/protocol/pdudiagnostics.cpp" line="-10"/>
        <location line="+1"/>
        <location line="+9"/>
        <location line="+2"/>
        <location line="+1"/>
        <location line="+1"/>
        <source>Data</source>
        <translation>Data</translation>
    </message>
    <message>
        <location line="+68"/>
        <location filename="../../core/protocol/pdumultiplewrite.cpp" line="+18"/>
        <location line="+6"/>
        <source>Start address</source>
        <translation>Alamat awal</translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../../core/protocol/pdumultiplewrite.cpp" line="-4"/>
        <location line="+6"/>
        <source>Quantity</source>
        <translation>Jumlah</translation>
    </message>
    <message>
        <location line="+18"/>
        <location filename="../../core/protocol/pducommevents.cpp" line="+161"/>
        <location filename="../../core/protocol/pdufilerecord.cpp" line="+84"/>
        <location line="+67"/>
        <location filename="../../core/protocol/pdumaskfifo.cpp" line="+62"/>
        <location filename="../../core/protocol/pdumultiplewrite.cpp" line="+24"/>
        <location filename="../../core/protocol/pdureadbits.cpp" line="+24"/>
        <location filename="../../core/protocol/pdureportserverid.cpp" line="+25"/>
        <source>Byte count</source>
        <translation>Jumlah byte</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Register</source>
        <translation>Register</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Register index</source>
        <translation>Indeks register</translation>
    </message>
    <message>
        <location line="+25"/>
        <location filename="../../core/protocol/pducommevents.cpp" line="-29"/>
        <location filename="../../core/protocol/pdureportserverid.cpp" line="+22"/>
        <location line="+5"/>
        <location filename="../../core/protocol/pdusinglewrite.cpp" line="+33"/>
        <source>ON</source>
        <translation>ON</translation>
    </message>
    <message>
        <location line="+0"/>
        <location filename="../../core/protocol/pducommevents.cpp" line="+0"/>
        <location filename="../../core/protocol/pdureportserverid.cpp" line="-5"/>
        <location line="+3"/>
        <location filename="../../core/protocol/pdusinglewrite.cpp" line="+2"/>
        <source>OFF</source>
        <translation>OFF</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Incomplete register</source>
        <translation>Register tidak lengkap</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Padding bits</source>
        <translation>Bit pengisi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unused high bits of the last data byte</source>
        <translation>bit atas byte data terakhir yang tidak dipakai</translation>
    </message>
    <message>
        <location filename="../../core/protocol/pducommevents.cpp" line="-28"/>
        <source>Ready: no previous command is in progress</source>
        <translation>Siap: tidak ada perintah sebelumnya yang sedang berjalan</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Busy: a previous command is still being processed</source>
        <translation>Sibuk: perintah sebelumnya masih diproses</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Exception status</source>
        <translation>Status pengecualian</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Output</source>
        <translation>Output</translation>
    </message>
    <message>
        <location line="+13"/>
        <location line="+19"/>
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <location line="-18"/>
        <location line="+19"/>
        <source>Event count</source>
        <translation>Jumlah event</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Message count</source>
        <translation>Jumlah pesan</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Event</source>
        <translation>Event</translation>
    </message>
    <message>
        <location filename="../../core/protocol/pdudeviceid.cpp" line="+29"/>
        <source>Basic device identification (stream access)</source>
        <translation>Identifikasi perangkat dasar (akses stream)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Regular device identification (stream access)</source>
        <translation>Identifikasi perangkat reguler (akses stream)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Extended device identification (stream access)</source>
        <translation>Identifikasi perangkat diperluas (akses stream)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>One specific identification object (individual access)</source>
        <translation>Satu objek identifikasi tertentu (akses individual)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Undefined read device ID code</source>
        <translation>Kode baca ID perangkat tidak terdefinisi</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>VendorName</source>
        <translation>VendorName</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ProductCode</source>
        <translation>ProductCode</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>MajorMinorRevision</source>
        <translation>MajorMinorRevision</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>VendorUrl</source>
        <translation>VendorUrl</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ProductName</source>
        <translation>ProductName</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ModelName</source>
        <translation>ModelName</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>UserApplicationName</source>
        <translation>UserApplicationName</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reserved object</source>
        <translation>Objek cadangan</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Private object (extended, device dependent)</source>
        <translation>Objek privat (diperluas, bergantung perangkat)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Basic identification (stream access only)</source>
        <translation>Identifikasi dasar (hanya akses stream)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Regular identification (stream access only)</source>
        <translation>Identifikasi reguler (hanya akses stream)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Extended identification (stream access only)</source>
        <translation>Identifikasi diperluas (hanya akses stream)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Basic identification (stream access and individual access)</source>
        <translation>Identifikasi dasar (akses stream dan akses individual)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Regular identification (stream access and individual access)</source>
        <translation>Identifikasi reguler (akses stream dan akses individual)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Extended identification (stream access and individual access)</source>
        <translation>Identifikasi diperluas (akses stream dan akses individual)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Undefined conformity level</source>
        <translation>Tingkat kesesuaian tidak terdefinisi</translation>
    </message>
    <message>
        <location line="+26"/>
        <location line="+80"/>
        <source>Read device ID code</source>
        <translation>Kode baca ID perangkat</translation>
    </message>
    <message>
        <location line="-79"/>
        <location line="+42"/>
        <source>Object ID</source>
        <translation>ID objek</translation>
    </message>
    <message>
        <location line="-3"/>
        <source>Object</source>
        <translation>Objek</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Object length</source>
        <translation>Panjang objek</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Object value</source>
        <translation>Nilai objek</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Conformity level</source>
        <translation>Tingkat kesesuaian</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>More follows</source>
        <translation>Masih ada lanjutan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Next object ID</source>
        <translation>ID objek berikutnya</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Number of objects</source>
        <translation>Jumlah objek</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>No more objects</source>
        <translation>Tidak ada objek lagi</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>More objects follow: ask again from the next object ID</source>
        <translation>Masih ada objek berikutnya: minta lagi mulai dari ID objek berikutnya</translation>
    </message>
    <message>
        <location line="+56"/>
        <source>MEI type</source>
        <translation>Tipe MEI</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Read Device Identification</source>
        <translation>Baca Identifikasi Perangkat</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>CANopen General Reference</source>
        <translation>Referensi Umum CANopen</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Reserved MEI type</source>
        <translation>Tipe MEI cadangan</translation>
    </message>
    <message>
        <location filename="../../core/protocol/pdudiagnostics.cpp" line="+22"/>
        <source>BS (backspace)</source>
        <translation>BS (backspace)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>HT (tab)</source>
        <translation>HT (tab)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>LF (line feed, the default delimiter)</source>
        <translation>LF (line feed, delimiter bawaan)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>FF (form feed)</source>
        <translation>FF (form feed)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>CR (carriage return)</source>
        <translation>CR (carriage return)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>DC1 (XON)</source>
        <translation>DC1 (XON)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>DC3 (XOFF)</source>
        <translation>DC3 (XOFF)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&apos; &apos; (space)</source>
        <translation>&apos; &apos; (spasi)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>not an ASCII character</source>
        <translation>bukan karakter ASCII</translation>
    </message>
    <message>
        <location line="-52"/>
        <location line="+117"/>
        <location line="+7"/>
        <source>Echo data</source>
        <translation>Data echo</translation>
    </message>
    <message>
        <location line="-123"/>
        <source>Restart option</source>
        <translation>Opsi restart</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Diagnostic register</source>
        <translation>Register diagnostik</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Bus message count</source>
        <translation>Jumlah pesan bus</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bus communication error count</source>
        <translation>Jumlah error komunikasi bus</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bus exception error count</source>
        <translation>Jumlah error pengecualian bus</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Server message count</source>
        <translation>Jumlah pesan server</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Server no response count</source>
        <translation>Jumlah tanpa respons server</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Server NAK count</source>
        <translation>Jumlah NAK server</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Server busy count</source>
        <translation>Jumlah server sibuk</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bus character overrun count</source>
        <translation>Jumlah overrun karakter bus</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Reserved (legacy Modicon: Return IOP Overrun Count)</source>
        <translation>Cadangan (Modicon lama: Return IOP Overrun Count)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reserved (legacy Modicon: Get/Clear Modbus Plus Statistics)</source>
        <translation>Cadangan (Modicon lama: Get/Clear Modbus Plus Statistics)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reserved sub-function</source>
        <translation>Sub-fungsi cadangan</translation>
    </message>
    <message>
        <location line="+121"/>
        <source>Restart, keep the communications event log</source>
        <translation>Restart, simpan log event komunikasi</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Restart and clear the communications event log</source>
        <translation>Restart dan kosongkan log event komunikasi</translation>
    </message>
    <message>
        <location line="-138"/>
        <location line="+150"/>
        <source>ASCII input delimiter</source>
        <translation>Delimiter input ASCII</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Padding</source>
        <translation>Pengisi</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>Sub-function</source>
        <translation>Sub-fungsi</translation>
    </message>
    <message>
        <location filename="../../core/protocol/pdufilerecord.cpp" line="-123"/>
        <source>file record</source>
        <translation>record file</translation>
    </message>
    <message>
        <location line="+12"/>
        <location line="+184"/>
        <source>Reference type</source>
        <translation>Tipe referensi</translation>
    </message>
    <message>
        <location line="-183"/>
        <source>File number</source>
        <translation>Nomor file</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Record number</source>
        <translation>Nomor record</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Record length</source>
        <translation>Panjang record</translation>
    </message>
    <message>
        <location line="+59"/>
        <source>Incomplete sub-request</source>
        <translation>Sub-permintaan tidak lengkap</translation>
    </message>
    <message>
        <location line="+23"/>
        <location line="+125"/>
        <source>Sub-request</source>
        <translation>Sub-permintaan</translation>
    </message>
    <message>
        <location line="-62"/>
        <location line="+62"/>
        <source>Sub-response</source>
        <translation>Sub-respons</translation>
    </message>
    <message>
        <location line="-61"/>
        <source>Sub-response length</source>
        <translation>Panjang sub-respons</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>Record</source>
        <translation>Record</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Record index</source>
        <translation>Indeks record</translation>
    </message>
    <message>
        <location filename="../../core/protocol/pdumaskfifo.cpp" line="-46"/>
        <source>Reference address</source>
        <translation>Alamat referensi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>AND mask</source>
        <translation>Mask AND</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>OR mask</source>
        <translation>Mask OR</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>FIFO pointer address</source>
        <translation>Alamat pointer FIFO</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>bits kept from the current contents (1 = keep)</source>
        <translation>bit yang dipertahankan dari isi saat ini (1 = pertahankan)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bits set where the AND mask is 0: result = (current AND and_mask) OR (or_mask AND NOT and_mask)</source>
        <translation>bit yang di-set di posisi mask AND bernilai 0: hasil = (isi_saat_ini AND and_mask) OR (or_mask AND NOT and_mask)</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>FIFO count</source>
        <translation>Jumlah FIFO</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>FIFO entry</source>
        <translation>Isi FIFO</translation>
    </message>
    <message>
        <location filename="../../core/protocol/pdureadbits.cpp" line="+17"/>
        <source>Coil</source>
        <translation>Coil</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Discrete input</source>
        <translation>Discrete input</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Coil index</source>
        <translation>Indeks coil</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Input index</source>
        <translation>Indeks input</translation>
    </message>
    <message>
        <location filename="../../core/protocol/pdureadwrite.cpp" line="+18"/>
        <source>Read start address</source>
        <translation>Alamat awal baca</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Quantity to read</source>
        <translation>Jumlah yang dibaca</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Write start address</source>
        <translation>Alamat awal tulis</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Quantity to write</source>
        <translation>Jumlah yang ditulis</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Write byte count</source>
        <translation>Jumlah byte tulis</translation>
    </message>
    <message>
        <location filename="../../core/protocol/pdureportserverid.cpp" line="-24"/>
        <source>Server ID</source>
        <translation>ID server</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Run indicator status</source>
        <translation>Status indikator jalan</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Additional data</source>
        <translation>Data tambahan</translation>
    </message>
    <message>
        <location filename="../../core/protocol/pdusinglewrite.cpp" line="-21"/>
        <source>Output address</source>
        <translation>Alamat output</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output value</source>
        <translation>Nilai output</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Register address</source>
        <translation>Alamat register</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Register value</source>
        <translation>Nilai register</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>illegal (neither ON nor OFF)</source>
        <translation>tidak sah (bukan ON maupun OFF)</translation>
    </message>
    <message>
        <location filename="../../core/protocol/registerformat.cpp" line="+14"/>
        <source>unsigned 16-bit</source>
        <translation>16-bit tak bertanda</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>signed 16-bit</source>
        <translation>16-bit bertanda</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>16-bit hex</source>
        <translation>hex 16-bit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>16-bit binary</source>
        <translation>biner 16-bit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ASCII, two characters per register</source>
        <translation>ASCII, dua karakter per register</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unsigned 32-bit</source>
        <translation>32-bit tak bertanda</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>signed 32-bit</source>
        <translation>32-bit bertanda</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unsigned 64-bit</source>
        <translation>64-bit tak bertanda</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>signed 64-bit</source>
        <translation>64-bit bertanda</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>float32 (IEEE 754 single)</source>
        <translation>float32 (IEEE 754 presisi tunggal)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>float64 (IEEE 754 double)</source>
        <translation>float64 (IEEE 754 presisi ganda)</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>big endian</source>
        <translation>big endian</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>word swap</source>
        <translation>tukar word</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+102"/>
        <source>byte swap</source>
        <translation>tukar byte</translation>
    </message>
    <message>
        <location line="-101"/>
        <source>little endian</source>
        <translation>little endian</translation>
    </message>
    <message>
        <location line="+101"/>
        <source>high byte first</source>
        <translation>byte atas dulu</translation>
    </message>
    <message>
        <location filename="../../core/protocol/streamframer.cpp" line="+15"/>
        <source>no frame start</source>
        <translation>tidak ada awal frame</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>invalid MBAP header</source>
        <translation>header MBAP tidak valid</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CRC mismatch</source>
        <translation>CRC tidak cocok</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>impossible function code</source>
        <translation>kode fungsi yang mustahil</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>function code without a length rule while resynchronising</source>
        <translation>kode fungsi tanpa aturan panjang saat sinkronisasi ulang</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>frame restarted by &apos;:&apos;</source>
        <translation>frame dimulai ulang oleh &apos;:&apos;</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>frame too long</source>
        <translation>frame terlalu panjang</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>incomplete frame at silence</source>
        <translation>frame tidak lengkap saat jeda</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>rest of a frame cut by a gap</source>
        <translation>sisa frame yang terpotong oleh celah</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>unknown reason</source>
        <translation>alasan tidak diketahui</translation>
    </message>
    <message>
        <location filename="../../core/protocol/pdudissector.cpp" line="-51"/>
        <source>(coil 0xxxx, numbered from 1: PDU address + 1)</source>
        <translation>(coil 0xxxx, bernomor mulai 1: alamat PDU + 1)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>(discrete input 1xxxx, numbered from 1: PDU address + 1)</source>
        <translation>(input diskret 1xxxx, bernomor mulai 1: alamat PDU + 1)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>(input register 3xxxx, numbered from 1: PDU address + 1)</source>
        <translation>(register input 3xxxx, bernomor mulai 1: alamat PDU + 1)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>(holding register 4xxxx, numbered from 1: PDU address + 1)</source>
        <translation>(register holding 4xxxx, bernomor mulai 1: alamat PDU + 1)</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Modicon reference</source>
        <translation>Referensi Modicon</translation>
    </message>
    <message>
        <location line="+10"/>
        <location line="+7"/>
        <source>Function code</source>
        <translation>Kode fungsi</translation>
    </message>
    <message>
        <location line="+82"/>
        <source>Function in error</source>
        <translation>Fungsi yang error</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Exception code</source>
        <translation>Kode pengecualian</translation>
    </message>
    <message>
        <location filename="../../core/protocol/dissector.cpp" line="+34"/>
        <source>Frame too long</source>
        <translation>Frame terlalu panjang</translation>
    </message>
</context>
<context>
    <name>mbscope::FieldTreeModel</name>
    <message>
        <location filename="../../ui/decode/fieldtreemodel.cpp" line="+225"/>
        <source>Offset</source>
        <translation>Offset</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bytes</source>
        <translation>Byte</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Field</source>
        <translation>Bidang</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Value</source>
        <translation>Nilai</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Problem</source>
        <translation>Masalah</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Byte offset of the field in the frame, counted from 0</source>
        <translation>Offset byte field di dalam frame, dihitung dari 0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The field&apos;s raw bytes as they appear in the frame</source>
        <translation>Byte mentah field sebagaimana muncul di frame</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The field&apos;s name; per-item fields show their register, coil or object address</source>
        <translation>Nama field; field per item menampilkan alamat register, coil atau objeknya</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The value and what it means</source>
        <translation>Nilai dan artinya</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>What is wrong with the field and what was expected</source>
        <translation>Apa yang salah pada field dan apa yang diharapkan</translation>
    </message>
</context>
<context>
    <name>mbscope::FrameInspector</name>
    <message>
        <location filename="../../ui/decode/frameinspector.cpp" line="+130"/>
        <source>No frame</source>
        <translation>Tidak ada frame</translation>
    </message>
</context>
<context>
    <name>mbscope::HexView</name>
    <message>
        <location filename="../../ui/decode/hexview.cpp" line="+379"/>
        <source>Offset %1 (0x%2): 0x%3 = %4</source>
        <translation>Offset %1 (0x%2): 0x%3 = %4</translation>
    </message>
</context>
<context>
    <name>mbscope::HistogramChart</name>
    <message>
        <location filename="../../ui/common/histogramchart.cpp" line="+68"/>
        <source>latency (%1)</source>
        <translation>latensi (%1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>transactions</source>
        <translation>transaksi</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>no answered transactions: no latency to show</source>
        <translation>tidak ada transaksi yang terjawab: tidak ada latensi untuk ditampilkan</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>latency (%1), logarithmic</source>
        <translation>latensi (%1), logaritmik</translation>
    </message>
</context>
<context>
    <name>mbscope::InferDialog</name>
    <message>
        <location filename="../../ui/discovery/inferdialog.cpp" line="+41"/>
        <source> ms</source>
        <translation> md</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Sample and infer</source>
        <translation>&amp;Ambil sampel dan simpulkan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sto&amp;p</source>
        <translation>&amp;Hentikan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Read again</source>
        <translation>Baca &amp;lagi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sa&amp;ve profile…</source>
        <translation>Simpan &amp;profil…</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Infer types</source>
        <translation>Simpulkan tipe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>How many times every block is read: the more, the surer the kinds and relations.</source>
        <translation>Berapa kali setiap blok dibaca: makin banyak, makin yakin jenis dan hubungannya.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>From the start of one round of reads to the start of the next.</source>
        <translation>Dari awal satu putaran pembacaan sampai awal putaran berikutnya.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Unit:</source>
        <translation>Unit:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>every</source>
        <translation>setiap</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Sa&amp;mples:</source>
        <translation>Sa&amp;mpel:</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Read every block once more and show the values under every reading.</source>
        <translation>Baca setiap blok sekali lagi dan tampilkan nilai di bawah setiap bacaan.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save the draft as a device profile that mbscope simulate --profile serves and mbscope export-map exports: the rows checked OK are confirmed, the others stay guesses.</source>
        <translation>Simpan draf sebagai profil perangkat yang dilayani mbscope simulate --profile dan diekspor mbscope export-map: baris yang dicentang OK dikonfirmasi, sisanya tetap tebakan.</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>%1 of %2 values confirmed. Check the reading whose numbers you recognise, or OK to keep the guess; then save the profile.</source>
        <translation>%1 dari %2 nilai dikonfirmasi. Centang bacaan yang angkanya Anda kenali, atau OK untuk mempertahankan tebakan; lalu simpan profilnya.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Reads the blocks of the map again and again, then proposes each value&apos;s type, order, scale, unit and kind. Never writes.</source>
        <translation>Membaca blok-blok peta berulang kali, lalu mengusulkan tipe, urutan, skala, satuan, dan jenis setiap nilai. Tidak pernah menulis.</translation>
    </message>
    <message numerus="yes">
        <location line="+16"/>
        <source>%1, unit %2: %n block(s) of the map</source>
        <translation>
            <numerusform>%1, unit %2: %n blok dari peta</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>, %n address(es)</source>
        <translation>
            <numerusform>, %n alamat</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+32"/>
        <source>Reading the blocks %n time(s)…</source>
        <translation>
            <numerusform>Membaca blok-blok %n kali…</numerusform>
        </translation>
    </message>
    <message>
        <location line="+49"/>
        <source>Too few reads answered to infer anything.</source>
        <translation>Terlalu sedikit pembacaan yang dijawab untuk menyimpulkan apa pun.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Nothing could be read: %1</source>
        <translation>Tidak ada yang bisa dibaca: %1</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Cannot save %1: %2</source>
        <translation>Tidak dapat menyimpan %1: %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Saved %1 (%2 of %3 values confirmed): mbscope simulate --profile %1 serves it, mbscope export-map %1 --to FORMAT exports it.</source>
        <translation>Tersimpan %1 (%2 dari %3 nilai dikonfirmasi): mbscope simulate --profile %1 melayaninya, mbscope export-map %1 --to FORMAT mengekspornya.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Save profile</source>
        <translation>Simpan profil</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Device profiles (*.json)</source>
        <translation>Profil perangkat (*.json)</translation>
    </message>
</context>
<context>
    <name>mbscope::InferDraftModel</name>
    <message>
        <location filename="../../ui/discovery/inferdraftmodel.cpp" line="+116"/>
        <source>The guess: %1</source>
        <translation>Tebakan: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Check to read the value as %1 instead</source>
        <translation>Centang untuk membaca nilai sebagai %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Scale (%1 %): %2</source>
        <translation>Skala (%1 %): %2</translation>
    </message>
    <message>
        <location line="+66"/>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Address</source>
        <translation>Alamat</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Name</source>
        <translation>Nama</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Unit</source>
        <translation>Satuan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Kind</source>
        <translation>Jenis</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sure</source>
        <translation>Yakin</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Guess</source>
        <translation>Tebakan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reading %1</source>
        <translation>Bacaan %1</translation>
    </message>
</context>
<context>
    <name>mbscope::LatencyAnalysis</name>
    <message>
        <location filename="../../ui/analysis/latencyanalysis.cpp" line="+22"/>
        <source>Latency histogram</source>
        <translation>Histogram latensi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Compare</source>
        <translation>Bandingkan</translation>
    </message>
</context>
<context>
    <name>mbscope::LatencyComparePanel</name>
    <message>
        <location filename="../../ui/analysis/latencycomparepanel.cpp" line="+72"/>
        <source>A run (current poll, reference, capture) and a request item, or all of its transactions</source>
        <translation>Satu run (polling saat ini, referensi, capture) dan satu item permintaan, atau semua transaksinya</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Linear bins</source>
        <translation>Bin linear</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Logarithmic bins</source>
        <translation>Bin logaritmik</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>against</source>
        <translation>terhadap</translation>
    </message>
    <message>
        <location line="+62"/>
        <source>%1, %2</source>
        <translation>%1, %2</translation>
    </message>
    <message>
        <location line="+49"/>
        <source>%1 (%2 answered)</source>
        <translation>%1 (%2 terjawab)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>median %1 %2</source>
        <translation>median %1 %2</translation>
    </message>
</context>
<context>
    <name>mbscope::LatencyHistogramPanel</name>
    <message>
        <location filename="../../ui/analysis/latencyhistogrampanel.cpp" line="+51"/>
        <source>Which run to show: the current poll, the kept reference or an opened capture</source>
        <translation>Run mana yang ditampilkan: polling saat ini, referensi yang disimpan, atau capture yang dibuka</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>All transactions, or those of one request item of the poll</source>
        <translation>Semua transaksi, atau transaksi satu item permintaan dari polling</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Linear bins</source>
        <translation>Bin linear</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Logarithmic bins</source>
        <translation>Bin logaritmik</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bins of equal width, or bins a constant factor apart for a long tail</source>
        <translation>Bin dengan lebar sama, atau bin berjarak faktor tetap untuk ekor yang panjang</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Keep as reference</source>
        <translation>&amp;Simpan sebagai referensi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Keep the current poll&apos;s figures to compare later runs with (Compare tab)</source>
        <translation>Simpan angka polling saat ini untuk dibandingkan dengan run berikutnya (tab Bandingkan)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Fit</source>
        <translation>&amp;Paskan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Show the whole histogram again after zooming or panning</source>
        <translation>Tampilkan lagi seluruh histogram setelah zoom atau geser</translation>
    </message>
    <message>
        <location line="+132"/>
        <source>Overall</source>
        <translation>Keseluruhan</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>min</source>
        <translation>min</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>median</source>
        <translation>median</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>p95</source>
        <translation>p95</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>p99</source>
        <translation>p99</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>max</source>
        <translation>maks</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 %2 %3</source>
        <translation>%1 %2 %3</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1, %2</source>
        <translation>%1, %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 transactions, %2 answered</source>
        <translation>%1 transaksi, %2 terjawab</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>; latency from the computed end of each request&apos;s transmission</source>
        <translation>; latensi dihitung dari akhir transmisi tiap permintaan</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>; latency from the computed end of transmission (%1) or the write (%2)</source>
        <translation>; latensi dari akhir transmisi yang dihitung (%1) atau dari penulisan (%2)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>; latency from each request&apos;s write</source>
        <translation>; latensi dari penulisan tiap permintaan</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>; warning: %1 answers faster than the serial line</source>
        <translation>; peringatan: %1 jawaban lebih cepat daripada saluran serial</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 answers came before the serial line could have carried the request and the answer at its baud rate: the link does not honour it (a pseudo terminal, or a USB adapter that buffers). Their latency is measured from the write.</source>
        <translation>%1 jawaban tiba sebelum saluran serial sempat membawa permintaan dan jawabannya pada baud rate-nya: tautan ini tidak mematuhinya (terminal semu, atau adaptor USB yang menyangga). Latensinya diukur dari penulisan.</translation>
    </message>
</context>
<context>
    <name>mbscope::LatencyRuns</name>
    <message>
        <location filename="../../ui/analysis/latencyruns.cpp" line="+57"/>
        <source>Current poll</source>
        <translation>Polling saat ini</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Reference</source>
        <translation>Referensi</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Capture: %1</source>
        <translation>Capture: %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>overall</source>
        <translation>keseluruhan</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>item %1</source>
        <translation>item %1</translation>
    </message>
</context>
<context>
    <name>mbscope::LatencySource</name>
    <message>
        <location filename="../../ui/analysis/latencysource.cpp" line="+49"/>
        <source>All bench traffic</source>
        <translation>Semua lalu lintas bangku uji</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Watch link %1</source>
        <translation>Link pantauan %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Watch %1</source>
        <translation>Pantauan %1</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Whose latency to show: all the bench&apos;s traffic, the polls of one link of the watches, or those of one watch (Watches tab, while the watches poll)</source>
        <translation>Latensi siapa yang ditampilkan: semua lalu lintas bangku uji, polling satu link pantauan, atau polling satu pantauan (tab Pantauan, selama pantauan berjalan)</translation>
    </message>
</context>
<context>
    <name>mbscope::LatencyStatisticsModel</name>
    <message>
        <location filename="../../ui/analysis/latencystatisticsmodel.cpp" line="+38"/>
        <source>Transactions</source>
        <translation>Transaksi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ok</source>
        <translation>Ok</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Exceptions</source>
        <translation>Pengecualian</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Exception %1 %2</source>
        <translation>Pengecualian %1 %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Timeouts</source>
        <translation>Waktu habis</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CRC errors</source>
        <translation>Error CRC</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Malformed</source>
        <translation>Cacat</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Unexpected</source>
        <translation>Tak terduga</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Late</source>
        <translation>Terlambat</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Link errors</source>
        <translation>Error link</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Faster than the line (from the write)</source>
        <translation>Lebih cepat daripada saluran (dari penulisan)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source> (within 0.1 %)</source>
        <translation> (paling jauh 0,1 % dari nilai tepatnya)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Latency min</source>
        <translation>Latensi min</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Latency mean</source>
        <translation>Latensi rata-rata</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Latency median</source>
        <translation>Latensi median</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Latency p90</source>
        <translation>Latensi p90</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Latency p95</source>
        <translation>Latensi p95</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Latency p99</source>
        <translation>Latensi p99</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Latency max</source>
        <translation>Latensi maks</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Latency std. deviation</source>
        <translation>Simpangan baku latensi</translation>
    </message>
    <message>
        <location line="+77"/>
        <source>–</source>
        <translation>–</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Figure</source>
        <translation>Besaran</translation>
    </message>
</context>
<context>
    <name>mbscope::LatencyTimeGraphs</name>
    <message>
        <location filename="../../ui/analysis/latencytimegraphs.cpp" line="+31"/>
        <source>answered (%1)</source>
        <translation>terjawab (%1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>exceptions (%1)</source>
        <translation>pengecualian (%1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no usable answer (%1), drawn at 0</source>
        <translation>tanpa jawaban yang bisa dipakai (%1), digambar di 0</translation>
    </message>
</context>
<context>
    <name>mbscope::LatencyTimePanel</name>
    <message>
        <location filename="../../ui/analysis/latencytimepanel.cpp" line="+29"/>
        <source>time since the first request (s)</source>
        <translation>waktu sejak permintaan pertama (s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>latency (ms)</source>
        <translation>latensi (ms)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>t = %1 s</source>
        <translation>t = %1 s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>answered</source>
        <translation>dijawab</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>exception</source>
        <translation>pengecualian</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no usable answer (timeout or bad answer)</source>
        <translation>tanpa jawaban yang bisa dipakai (waktu habis atau jawaban buruk)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Keep every transaction in view as new ones arrive</source>
        <translation>Jaga semua transaksi tetap terlihat saat transaksi baru masuk</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Forget the points shown; new transactions start a new time axis</source>
        <translation>Lupakan titik yang ditampilkan; transaksi baru memulai sumbu waktu baru</translation>
    </message>
    <message>
        <location line="+81"/>
        <source>%1 transactions: %2 answered, %3 exceptions, %4 without a usable answer</source>
        <translation>%1 transaksi: %2 terjawab, %3 pengecualian, %4 tanpa jawaban yang bisa dipakai</translation>
    </message>
</context>
<context>
    <name>mbscope::LineScanDialog</name>
    <message>
        <location filename="../../ui/discovery/linescandialog.cpp" line="+56"/>
        <source> ms</source>
        <translation> md</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop at the &amp;first setting that answers</source>
        <translation>Berhenti pada pengaturan &amp;pertama yang menjawab</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Start</source>
        <translation>&amp;Mulai</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sto&amp;p</source>
        <translation>&amp;Hentikan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Use this setting</source>
        <translation>&amp;Gunakan pengaturan ini</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Find a serial line&apos;s settings</source>
        <translation>Cari pengaturan jalur serial</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The serial port, as rtu:///dev/ttyUSB0 or ascii:///dev/ttyUSB0: its line settings are the ones tried.</source>
        <translation>Port serial, sebagai rtu:///dev/ttyUSB0 atau ascii:///dev/ttyUSB0: pengaturan jalurnya yang dicoba.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Baud rates to try, in this order.</source>
        <translation>Laju baud yang dicoba, dengan urutan ini.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>empty: 1 on every setting, then 2-247</source>
        <translation>kosong: 1 pada setiap pengaturan, lalu 2-247</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Unit ids asked on every setting, e.g. 1 or 1, 17. Give the id when you know it: without one the scan is long.</source>
        <translation>Id unit yang ditanya pada setiap pengaturan, mis. 1 atau 1, 17. Berikan id-nya bila Anda tahu: tanpa id pemindaian lama.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>How long each request waits, plus the time the request and a long answer take on the line at each rate.</source>
        <translation>Berapa lama setiap permintaan menunggu, ditambah waktu yang dipakai permintaan dan jawaban panjang di jalur pada setiap laju.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Even</source>
        <translation>Ge&amp;nap</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>&amp;None</source>
        <translation>&amp;Tanpa</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>&amp;Odd</source>
        <translation>Ganji&amp;l</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>1 stop bit</source>
        <translation>1 bit stop</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>2 stop bits</source>
        <translation>2 bit stop</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>&amp;Target:</source>
        <translation>Tu&amp;juan:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Baud rates:</source>
        <translation>Laju &amp;baud:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parity, stop bits:</source>
        <translation>Paritas, bit stop:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Unit i&amp;ds:</source>
        <translation>I&amp;d unit:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>T&amp;imeout:</source>
        <translation>Batas &amp;waktu:</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Setting</source>
        <translation>Pengaturan</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Unit</source>
        <translation>Unit</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Result</source>
        <translation>Hasil</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Put the port with the selected setting that worked (or the first) in the unit scan&apos;s target.</source>
        <translation>Pasang port dengan pengaturan terpilih yang berhasil (atau yang pertama) sebagai tujuan pemindaian unit.</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>The unit scan&apos;s target is now %1.</source>
        <translation>Tujuan pemindaian unit sekarang %1.</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1 of %2 tried, %3 answered</source>
        <translation>%1 dari %2 dicoba, %3 menjawab</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Asks the read on every setting until CRC-valid answers come back. Never writes.</source>
        <translation>Menanyakan baca itu pada setiap pengaturan sampai jawaban dengan CRC sah kembali. Tidak pernah menulis.</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Give the serial port, e.g. rtu:///dev/ttyUSB0.</source>
        <translation>Berikan port serial, mis. rtu:///dev/ttyUSB0.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Baud rates: give at least one, e.g. 9600, 19200.</source>
        <translation>Laju baud: berikan paling sedikit satu, mis. 9600, 19200.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Baud rates: &quot;%1&quot; is not a baud rate.</source>
        <translation>Laju baud: &quot;%1&quot; bukan laju baud.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Unit ids: &quot;%1&quot; is not an id from 1 to 247.</source>
        <translation>Id unit: &quot;%1&quot; bukan id dari 1 sampai 247.</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Choose at least one parity and one stop-bit count.</source>
        <translation>Pilih paling sedikit satu paritas dan satu jumlah bit stop.</translation>
    </message>
    <message>
        <location line="+49"/>
        <source>works: %1</source>
        <translation>berhasil: %1</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1 (unit %2)</source>
        <translation>%1 (unit %2)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The port failed: %1</source>
        <translation>Port gagal: %1</translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>No setting answered (%n tried).</source>
        <translation>
            <numerusform>Tidak ada pengaturan yang menjawab (%n dicoba).</numerusform>
        </translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Answered: %1.</source>
        <translation>Menjawab: %1.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stopped. %1</source>
        <translation>Dihentikan. %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Time limit reached. %1</source>
        <translation>Batas waktu tercapai. %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Several parities answered: this line does not carry the parity bit (a pseudo terminal, or a converter that ignores it), so the device&apos;s parity cannot be told here.</source>
        <translation>Beberapa paritas menjawab: jalur ini tidak membawa bit paritas (terminal semu, atau konverter yang mengabaikannya), jadi paritas perangkat tidak dapat ditentukan di sini.</translation>
    </message>
</context>
<context>
    <name>mbscope::LinkController</name>
    <message>
        <location filename="../../ui/link/linkcontroller.cpp" line="+153"/>
        <source>nothing is being recorded</source>
        <translation>tidak ada yang sedang direkam</translation>
    </message>
    <message>
        <location line="+18"/>
        <location line="+7"/>
        <source>cannot copy %1 to %2: %3</source>
        <translation>tidak dapat menyalin %1 ke %2: %3</translation>
    </message>
    <message>
        <location line="+71"/>
        <source>%1: listening only (nothing is sent)</source>
        <translation>%1: hanya mendengar (tidak ada yang dikirim)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: opening to listen</source>
        <translation>%1: membuka untuk mendengar</translation>
    </message>
    <message>
        <location line="-26"/>
        <source>%1: connecting…</source>
        <translation>%1: menyambungkan…</translation>
    </message>
    <message>
        <location line="-90"/>
        <source>the recording stopped: %1; what came before is in %2</source>
        <translation>perekaman berhenti: %1; yang datang sebelumnya ada di %2</translation>
    </message>
    <message>
        <location line="+133"/>
        <location line="+83"/>
        <location line="+10"/>
        <source>Not connected</source>
        <translation>Tidak tersambung</translation>
    </message>
    <message>
        <location line="-67"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>tap: masters at %1 → %2</source>
        <translation>sadap: master di %1 → %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source> (read-only)</source>
        <translation> (hanya baca)</translation>
    </message>
    <message>
        <location line="+130"/>
        <source>Poll %1: %2 transactions, %3 ok, %4 failed</source>
        <translation>Polling %1: %2 transaksi, %3 ok, %4 gagal</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stopped</source>
        <translation>dihentikan</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>finished</source>
        <translation>selesai</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>; latency min %1 ms, mean %2 ms, max %3 ms</source>
        <translation>; latensi min %1 ms, rata-rata %2 ms, maks %3 ms</translation>
    </message>
</context>
<context>
    <name>mbscope::LinkStatusWidget</name>
    <message>
        <location filename="../../ui/shell/linkstatuswidget.cpp" line="+19"/>
        <source>What the watches of the Watches tab sent and received on their own links</source>
        <translation>Yang dikirim dan diterima pantauan di tab Pantauan lewat link mereka sendiri</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>Not connected</source>
        <translation>Tidak tersambung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Connecting</source>
        <translation>Menyambungkan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Connected</source>
        <translation>Tersambung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Link failed</source>
        <translation>Link gagal</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>TX %1 B  RX %2 B  ·  %3</source>
        <translation>TX %1 B  RX %2 B  ·  %3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>1 request</source>
        <translation>1 permintaan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 requests</source>
        <translation>%1 permintaan</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>  ·  1 link error</source>
        <translation>  ·  1 error link</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>  ·  %1 link errors</source>
        <translation>  ·  %1 error link</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>This connection&apos;s traffic since Connect: bytes sent (TX) and received (RX), requests sent and link errors. A new connection counts from zero.</source>
        <translation>Lalu lintas koneksi ini sejak Sambung: byte terkirim (TX) dan diterima (RX), permintaan terkirim dan galat link. Koneksi baru menghitung dari nol.</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Watches: TX %1 B  RX %2 B  ·  %3</source>
        <translation>Pantauan: TX %1 B  RX %2 B  ·  %3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>1 poll</source>
        <translation>1 polling</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 polls</source>
        <translation>%1 polling</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>  ·  1 failed</source>
        <translation>  ·  1 gagal</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>  ·  %1 failed</source>
        <translation>  ·  %1 gagal</translation>
    </message>
</context>
<context>
    <name>mbscope::MainWindow</name>
    <message>
        <location filename="../../ui/shell/mainwindow.cpp" line="+96"/>
        <source>Ready</source>
        <translation>Siap</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>&amp;Answer</source>
        <translation>&amp;Jawaban</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Decode any frame</source>
        <translation>&amp;Dekode frame apa saja</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Watches</source>
        <translation>Pantauan</translation>
    </message>
    <message>
        <location line="+136"/>
        <source>Traffic</source>
        <translation>Lalu lintas</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Registers</source>
        <translation>Register</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Analysis</source>
        <translation>Analisis</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Simulator</source>
        <translation>Simulator</translation>
    </message>
    <message>
        <location line="+61"/>
        <source>The connection bar names no target: %1</source>
        <translation>Bilah koneksi tidak menyebut target: %1</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Plotting %1 in Analysis → Register trends</source>
        <translation>Menggambar %1 di Analisis → Tren register</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>%1 dock (F6: the next one)</source>
        <translation>Dok %1 (F6: dok berikutnya)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Disconnected: the session names no target that can be used (%1)</source>
        <translation>Terputus: sesi tidak menyebut target yang dapat dipakai (%1)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Connecting to the session&apos;s target %1</source>
        <translation>Menyambungkan ke target sesi %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Not sent (%1): connect first</source>
        <translation>Tidak terkirim (%1): sambungkan dulu</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Sent: %1; reading it back</source>
        <translation>Terkirim: %1; membacanya kembali</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Sent: %1</source>
        <translation>Terkirim: %1</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Not connected: press Connect to use %1 again</source>
        <translation>Tidak tersambung: tekan Sambungkan untuk memakai %1 lagi</translation>
    </message>
    <message>
        <location line="+54"/>
        <source>&amp;File</source>
        <translation>&amp;Berkas</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&amp;Quit</source>
        <translation>&amp;Keluar</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Wor&amp;kspace</source>
        <translation>Da&amp;ftar pantau</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>&amp;View</source>
        <translation>&amp;Tampilan</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Find in traffic</source>
        <translation>&amp;Cari di lalu lintas</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>&amp;Next dock</source>
        <translation>Dok &amp;berikutnya</translation>
    </message>
    <message numerus="yes">
        <location line="+30"/>
        <source>%n watch(es) added from the scan: Workspace &gt; Start all (F5) polls them.</source>
        <translation>
            <numerusform>%n pantauan ditambahkan dari pindaian: Daftar pantau &gt; Mulai semua (F5) membacanya.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>mbscope::MapResultTree</name>
    <message>
        <location filename="../../ui/discovery/mapresulttree.cpp" line="+39"/>
        <source>answers</source>
        <translation>menjawab</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>exception 01: not supported</source>
        <translation>eksepsi 01: tidak didukung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>exception %1 from a gateway: no device</source>
        <translation>pengecualian %1 dari gateway: tidak ada perangkat</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>exception %1: known, refused</source>
        <translation>eksepsi %1: dikenal, ditolak</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>silent</source>
        <translation>diam</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not asked</source>
        <translation>tidak ditanyakan</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Table or function</source>
        <translation>Tabel atau fungsi</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Found</source>
        <translation>Ditemukan</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Detail</source>
        <translation>Rincian</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>01 Coils</source>
        <translation>01 Coil</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>02 Discrete inputs</source>
        <translation>02 Input diskret</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>03 Holding registers</source>
        <translation>03 Register holding</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>04 Input registers</source>
        <translation>04 Register input</translation>
    </message>
    <message numerus="yes">
        <location line="+21"/>
        <source>addresses %1-%2 searched, %n request(s)</source>
        <translation>
            <numerusform>alamat %1–%2 dicari, %n permintaan</numerusform>
        </translation>
    </message>
    <message>
        <location line="+4"/>
        <source>no device: exception %1 from a gateway</source>
        <translation>tidak ada perangkat: pengecualian %1 dari gateway</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>not answered (exception 01 or silence)</source>
        <translation>tidak dijawab (eksepsi 01 atau diam)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>no address answered</source>
        <translation>tidak ada alamat yang menjawab</translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%n block(s)</source>
        <translation>
            <numerusform>%n blok</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>, largest read %1</source>
        <translation>, baca terbesar %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1-%2 (0x%3-0x%4)</source>
        <translation>%1–%2 (0x%3–0x%4)</translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%n address(es)</source>
        <translation>
            <numerusform>%n alamat</numerusform>
        </translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Optional functions</source>
        <translation>Fungsi opsional</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 of %2 known</source>
        <translation>%1 dari %2 dikenal</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Exception status (07)</source>
        <translation>Status eksepsi (07)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Server id (11)</source>
        <translation>Id server (11)</translation>
    </message>
</context>
<context>
    <name>mbscope::MapScanDialog</name>
    <message>
        <location filename="../../ui/discovery/mapscandialog.cpp" line="+43"/>
        <source>&amp;Optional functions (07, 08, 0B, 0C, 11, 14, 17, 18, 2B/0E)</source>
        <translation>Fungsi &amp;opsional (07, 08, 0B, 0C, 11, 14, 17, 18, 2B/0E)</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+1"/>
        <source> ms</source>
        <translation> md</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Start</source>
        <translation>&amp;Mulai</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sto&amp;p</source>
        <translation>&amp;Hentikan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save profile &amp;draft…</source>
        <translation>Simpan &amp;draf profil…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Add as watches</source>
        <translation>&amp;Tambahkan sebagai pantauan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>I&amp;nfer types…</source>
        <translation>&amp;Simpulkan tipe…</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Map a unit&apos;s registers</source>
        <translation>Petakan register sebuah unit</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The link of the unit. The scan opens a connection of its own.</source>
        <translation>Link unit tersebut. Pemindaian membuka sambungannya sendiri.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Between blocks, ask one address in this many: 1 finds every address, 16 every block of 16 addresses or more in about a sixteenth of the requests. A block found is mapped whole.</source>
        <translation>Di antara blok, tanyakan satu alamat dari sekian: 1 menemukan setiap alamat, 16 menemukan setiap blok 16 alamat atau lebih dengan sekitar seperenam belas permintaan. Blok yang ditemukan dipetakan utuh.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The scan stops after this many requests.</source>
        <translation>Pemindaian berhenti setelah permintaan sebanyak ini.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>to</source>
        <translation>sampai</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>step</source>
        <translation>langkah</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>0&amp;1 Coils</source>
        <translation>0&amp;1 Coil</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>0&amp;2 Discrete inputs</source>
        <translation>0&amp;2 Input diskret</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>0&amp;3 Holding</source>
        <translation>0&amp;3 Holding (register)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>0&amp;4 Input</source>
        <translation>0&amp;4 Input (register)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>gap</source>
        <translation>jeda</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>at most</source>
        <translation>paling banyak</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>requests</source>
        <translation>permintaan</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Target:</source>
        <translation>Tu&amp;juan:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Unit:</source>
        <translation>&amp;Unit:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Add&amp;resses:</source>
        <translation>&amp;Alamat:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Tables:</source>
        <translation>Tabel:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>T&amp;imeout:</source>
        <translation>Batas &amp;waktu:</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Save the map as a device profile that mbscope simulate --profile serves: the unit cloned into the simulator, to test against without the hardware.</source>
        <translation>Simpan peta sebagai profil perangkat yang dilayani mbscope simulate --profile: unit itu dikloning ke simulator, untuk diuji tanpa perangkat kerasnya.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Add a watch per block found to the window&apos;s watches.</source>
        <translation>Tambahkan satu pantauan per blok yang ditemukan ke pantauan jendela.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Read the blocks found again and again and propose each value&apos;s type, order, scale, unit and kind, to confirm or correct row by row (mbscope infer).</source>
        <translation>Baca blok yang ditemukan berulang kali dan usulkan tipe, urutan, skala, satuan, dan jenis setiap nilai, untuk dikonfirmasi atau dikoreksi baris demi baris (mbscope infer).</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>Reads every table&apos;s addresses (exception 02 says an address is missing). Never writes.</source>
        <translation>Membaca alamat setiap tabel (eksepsi 02 berarti alamat itu tidak ada). Tidak pernah menulis.</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Give the link of the unit, e.g. tcp://192.168.1.10:502.</source>
        <translation>Berikan link unit tersebut, mis. tcp://192.168.1.10:502.</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Choose a table or the optional functions: there is nothing to scan.</source>
        <translation>Pilih sebuah tabel atau fungsi opsional: tidak ada yang bisa dipindai.</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Mapping unit %1…</source>
        <translation>Memetakan unit %1…</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Map complete</source>
        <translation>Peta selesai</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stopped</source>
        <translation>Dihentikan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Time limit reached</source>
        <translation>Batas waktu tercapai</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Request limit reached</source>
        <translation>Batas permintaan tercapai</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The link failed</source>
        <translation>Link gagal</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The link failed: %1 cannot be reached.</source>
        <translation>Link gagal: %1 tidak dapat dijangkau.</translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>%1: %n address(es) found in %2 requests.</source>
        <translation>
            <numerusform>%1: %n alamat ditemukan dalam %2 permintaan.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+22"/>
        <source>%1 of %2 addresses searched</source>
        <translation>%1 dari %2 alamat dicari</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Cannot save %1: %2</source>
        <translation>Tidak dapat menyimpan %1: %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Saved %1: mbscope simulate --profile %1 serves this unit.</source>
        <translation>Tersimpan %1: mbscope simulate --profile %1 melayani unit ini.</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Save profile draft</source>
        <translation>Simpan draf profil</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Device profiles (*.json)</source>
        <translation>Profil perangkat (*.json)</translation>
    </message>
</context>
<context>
    <name>mbscope::NoticeBanner</name>
    <message>
        <location filename="../../ui/common/noticebanner.cpp" line="+46"/>
        <source>Dismiss</source>
        <translation>Tutup</translation>
    </message>
</context>
<context>
    <name>mbscope::PaceDialog</name>
    <message>
        <location filename="../../ui/link/pacedialog.cpp" line="+27"/>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>none</source>
        <translation>tidak ada</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Device pace</source>
        <translation>Tempo perangkat</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>How fast this device may be asked. Every request the window sends on the target keeps it (Send, Poll, sweeps), as gap=, warmup= and close=each of its URL do on the command line.</source>
        <translation>Seberapa cepat perangkat ini boleh ditanya. Setiap permintaan yang dikirim jendela ke target mematuhinya (Kirim, Poll, sapuan), seperti gap=, warmup= dan close=each pada URL-nya di baris perintah.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>No request sooner than this after the one before it was sent or its exchange ended</source>
        <translation>Tidak ada permintaan lebih cepat dari ini setelah permintaan sebelumnya dikirim atau pertukarannya selesai</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Nothing is sent sooner than this after the link opens (every time it opens)</source>
        <translation>Tidak ada yang dikirim lebih cepat dari ini setelah tautan terbuka (setiap kali terbuka)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A new connection for each request (the device hangs up after each answer)</source>
        <translation>Sambungan baru untuk setiap permintaan (perangkat menutup sambungan setelah setiap jawaban)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Only a stream link (TCP, RTU or ASCII over TCP, TLS) has a connection to hang up</source>
        <translation>Hanya tautan aliran (TCP, RTU atau ASCII lewat TCP, TLS) yang memiliki sambungan untuk ditutup</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>From &amp;profile…</source>
        <translation>Dari &amp;profil…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Take minGapMs, warmUpMs and closesAfterAnswer from a device profile&apos;s limits (as scan --timing --profile-out records them), with some to spare, as poll --profile keeps them</source>
        <translation>Ambil minGapMs, warmUpMs dan closesAfterAnswer dari batas profil perangkat (seperti yang dicatat scan --timing --profile-out), dengan sedikit cadangan, seperti yang dipatuhi poll --profile</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&amp;Gap between requests:</source>
        <translation>&amp;Jeda antar permintaan:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Warm-up after connecting:</source>
        <translation>&amp;Pemanasan setelah tersambung:</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Nothing taken: %1</source>
        <translation>Tidak ada yang diambil: %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>minGapMs %1 (%2 ms, 1 ms to spare)</source>
        <translation>minGapMs %1 (%2 ms, cadangan 1 ms)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>warmUpMs %1 (%2 ms, a tenth to spare)</source>
        <translation>warmUpMs %1 (%2 ms, cadangan sepersepuluh)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>closesAfterAnswer</source>
        <translation>closesAfterAnswer</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>not closesAfterAnswer (this link has no connection to hang up)</source>
        <translation>bukan closesAfterAnswer (tautan ini tidak memiliki sambungan untuk ditutup)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 has no minGapMs, warmUpMs or closesAfterAnswer: no pace.</source>
        <translation>%1 tidak memiliki minGapMs, warmUpMs atau closesAfterAnswer: tanpa tempo.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>From %1: %2.</source>
        <translation>Dari %1: %2.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Its maxQuantity (%1) is not applied: the window sends the request you build as it is; keep reads within it.</source>
        <translation>maxQuantity-nya (%1) tidak diterapkan: jendela mengirim permintaan yang Anda susun apa adanya; jaga pembacaan dalam batas itu.</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Device pace from a profile</source>
        <translation>Tempo perangkat dari profil</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Device profiles (*.json)</source>
        <translation>Profil perangkat (*.json)</translation>
    </message>
</context>
<context>
    <name>mbscope::PlanController</name>
    <message>
        <location filename="../../ui/session/plancontroller.cpp" line="+41"/>
        <source>The plan is already running.</source>
        <translation>Rencana uji sudah berjalan.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The session has no test plan: add a &quot;plan&quot; to the session document (see docs/sessions.md).</source>
        <translation>Sesi ini tidak punya rencana uji: tambahkan &quot;plan&quot; ke dokumen sesi (lihat docs/sessions.md).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stop the poll first: the plan&apos;s steps need the device to themselves.</source>
        <translation>Hentikan polling dulu: langkah-langkah rencana uji perlu memakai perangkat sendirian.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Connect to a device, or save a target in the session, to run the plan against.</source>
        <translation>Sambungkan ke perangkat, atau simpan target di sesi, untuk menjalankan rencana uji terhadapnya.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The session&apos;s target %1 is not a target: %2</source>
        <translation>Target sesi %1 bukan target: %2</translation>
    </message>
    <message>
        <location line="+51"/>
        <source>Steps: %1; passed %2, failed %3, errors %4, skipped %5; %6 s against %7.</source>
        <translation>Langkah: %1; lulus %2, gagal %3, error %4, dilewati %5; %6 s terhadap %7.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 The link failed: %2</source>
        <translation>%1 Link gagal: %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 Stopped before the end.</source>
        <translation>%1 Dihentikan sebelum selesai.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Passed. %1</source>
        <translation>Lulus. %1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Failed. %1</source>
        <translation>Gagal. %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Run the plan before exporting its results.</source>
        <translation>Jalankan rencana uji sebelum mengekspor hasilnya.</translation>
    </message>
</context>
<context>
    <name>mbscope::PlanPanel</name>
    <message>
        <location filename="../../ui/session/planpanel.cpp" line="+24"/>
        <source>Export the results as JUnit XML</source>
        <translation>Ekspor hasil sebagai JUnit XML</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>JUnit XML (*.xml);;All files (*)</source>
        <translation>JUnit XML (*.xml);;Semua berkas (*)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Run plan</source>
        <translation>Jalankan rencana</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Run the session&apos;s test plan against the connected device (or the session&apos;s target)</source>
        <translation>Jalankan rencana uji sesi terhadap perangkat yang tersambung (atau target sesi)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stop</source>
        <translation>Hentikan</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export JUnit XML…</source>
        <translation>Ekspor JUnit XML…</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>Running %1 against %2…</source>
        <translation>Menjalankan %1 terhadap %2…</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>the plan</source>
        <translation>rencana uji</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>This session has no test plan. Open a session with one (File &gt; Open), then run it.</source>
        <translation>Sesi ini tidak punya rencana uji. Buka sesi yang punya rencana uji (Berkas &gt; Buka), lalu jalankan.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The session&apos;s plan</source>
        <translation>Rencana uji sesi</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>The plan of %1</source>
        <translation>Rencana uji %1</translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%1 has %n step(s). Press Run plan to run it against the connected device.</source>
        <translation>
            <numerusform>%1 memiliki %n langkah. Tekan Jalankan rencana untuk menjalankannya terhadap perangkat yang tersambung.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+23"/>
        <source>%1 JUnit XML written to %2.</source>
        <translation>%1 JUnit XML ditulis ke %2.</translation>
    </message>
</context>
<context>
    <name>mbscope::PlanResultModel</name>
    <message>
        <location filename="../../ui/session/planresultmodel.cpp" line="+39"/>
        <source>PASS</source>
        <translation>LULUS</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>FAIL</source>
        <translation>GAGAL</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>ERROR</source>
        <translation>ERROR</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>SKIP</source>
        <translation>LEWATI</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>no answer</source>
        <translation>tanpa jawaban</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>answer %1</source>
        <translation>jawaban %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 = %2</source>
        <translation>%1 = %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>exception 0x%1</source>
        <translation>pengecualian 0x%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>any answer</source>
        <translation>jawaban apa pun</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the poll runs</source>
        <translation>polling berjalan</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>waits %1 ms</source>
        <translation>menunggu %1 ms</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>repeats, times: %1</source>
        <translation>diulang, kali: %1</translation>
    </message>
    <message>
        <location line="+62"/>
        <source>Result</source>
        <translation>Hasil</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Step</source>
        <translation>Langkah</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Expected</source>
        <translation>Diharapkan</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>What came</source>
        <translation>Yang datang</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Why it failed</source>
        <translation>Mengapa gagal</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>ms</source>
        <translation>ms</translation>
    </message>
</context>
<context>
    <name>mbscope::PlotCursor</name>
    <message>
        <location filename="../../ui/common/plotcursor.cpp" line="+117"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>mbscope::PlotExportMenu</name>
    <message>
        <location filename="../../ui/common/plotexportmenu.cpp" line="+20"/>
        <source>&amp;Save plot as…</source>
        <translation>&amp;Simpan plot sebagai…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Copy plot</source>
        <translation>Salin &amp;plot</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save the plot as a PNG image, an SVG drawing or a PDF document</source>
        <translation>Simpan plot sebagai gambar PNG, gambar SVG atau dokumen PDF</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Copy the plot to the clipboard as an image</source>
        <translation>Salin plot ke clipboard sebagai gambar</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Save plot</source>
        <translation>Simpan plot</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Plot saved to %1</source>
        <translation>Plot disimpan ke %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Plot not saved: %1</source>
        <translation>Plot tidak disimpan: %1</translation>
    </message>
</context>
<context>
    <name>mbscope::PlotFollower</name>
    <message>
        <location filename="../../ui/common/plotfollower.cpp" line="+11"/>
        <source>&amp;Follow</source>
        <translation>&amp;Ikuti</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>C&amp;lear</source>
        <translation>&amp;Kosongkan</translation>
    </message>
</context>
<context>
    <name>mbscope::PlotSaver</name>
    <message>
        <location filename="../../ui/common/plotsaver.cpp" line="+55"/>
        <source>&apos;%1&apos;: this mbscope was built without Qt SVG (Debian: qt6-svg-dev), so it cannot write SVG; use .png or .pdf</source>
        <translation>&apos;%1&apos;: mbscope ini dibuat tanpa Qt SVG (Debian: qt6-svg-dev), jadi tidak dapat menulis SVG; pakai .png atau .pdf</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&apos;%1&apos;: the plot&apos;s format comes from the file name, which must end in .png, .svg or .pdf</source>
        <translation>&apos;%1&apos;: format plot diambil dari nama berkas, yang harus berakhiran .png, .svg atau .pdf</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>PNG image (*.png)</source>
        <translation>Gambar PNG (*.png)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>SVG drawing (*.svg)</source>
        <translation>Gambar SVG (*.svg)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>PDF document (*.pdf)</source>
        <translation>Dokumen PDF (*.pdf)</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>cannot write %1</source>
        <translation>tidak dapat menulis %1</translation>
    </message>
</context>
<context>
    <name>mbscope::PreferencesDialog</name>
    <message>
        <location filename="../../ui/shell/preferencesdialog.cpp" line="+25"/>
        <source>&amp;Record all traffic of the window&apos;s connections</source>
        <translation>&amp;Rekam semua lalu lintas sambungan jendela</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Preferences</source>
        <translation>Preferensi</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>System language (%1)</source>
        <translation>Bahasa sistem (%1)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The language of menus, panels and messages. The command line and JSON output stay English.</source>
        <translation>Bahasa menu, panel dan pesan. Baris perintah dan keluaran JSON tetap berbahasa Inggris.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>The window&apos;s colours: the desktop&apos;s, or light or dark whatever the desktop uses. Rule colours in the watches stay readable in both.</source>
        <translation>Warna jendela: warna desktop, atau terang atau gelap apa pun yang dipakai desktop. Warna aturan di pantauan tetap terbaca di keduanya.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Language:</source>
        <translation>&amp;Bahasa:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>T&amp;heme:</source>
        <translation>Te&amp;ma:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start the built-in &amp;simulator and connect to it at every start</source>
        <translation>Jalankan &amp;simulator bawaan dan sambungkan setiap kali mulai</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Off: only the first run does; later starts open the last session (or put back the last target, disconnected) and the last layout.</source>
        <translation>Mati: hanya jalankan pertama yang melakukannya; mulai berikutnya membuka sesi terakhir (atau memasang kembali target terakhir, tidak tersambung) dan tata letak terakhir.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Every frame in and out is written to a traffic journal as it happens, one per connection; a saved session keeps its journal beside it. analyze, export and replay read journals.</source>
        <translation>Setiap frame masuk dan keluar ditulis ke jurnal lalu lintas saat terjadi, satu per sambungan; sesi yang disimpan menyimpan jurnalnya di sampingnya. analyze, export dan replay membaca jurnal.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Where journals are written until a session is saved (empty: the default shown)</source>
        <translation>Tempat jurnal ditulis sampai sesi disimpan (kosong: bawaan yang ditampilkan)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Browse…</source>
        <translation>&amp;Telusuri…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Capture folder</source>
        <translation>Folder capture</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>New journal &amp;part every (MiB):</source>
        <translation>Bagian jurnal bar&amp;u setiap (MiB):</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Keep at most (MiB):</source>
        <translation>Simpan &amp;paling banyak (MiB):</translation>
    </message>
    <message>
        <location line="-14"/>
        <source>A journal that reaches this size is closed and the recording goes on in a new part</source>
        <translation>Jurnal yang mencapai ukuran ini ditutup dan perekaman berlanjut di bagian baru</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The oldest journals in the capture folder are deleted to stay under this size (never one being written, never one beside a saved session)</source>
        <translation>Jurnal tertua di folder capture dihapus agar tetap di bawah ukuran ini (tidak pernah yang sedang ditulis, tidak pernah yang di samping sesi tersimpan)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Capture &amp;folder:</source>
        <translation>&amp;Folder capture:</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Recording</source>
        <translation>Perekaman</translation>
    </message>
    <message>
        <location line="+91"/>
        <source>mbscope --lang id (or en) chooses the language for one run.</source>
        <translation>mbscope --lang id (atau en) memilih bahasa untuk satu kali jalan.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The new language is used when mbscope is started again.</source>
        <translation>Bahasa yang baru dipakai saat mbscope dijalankan lagi.</translation>
    </message>
</context>
<context>
    <name>mbscope::RawRequestEditor</name>
    <message>
        <location filename="../../ui/compose/rawrequesteditor.cpp" line="+44"/>
        <source>Add MBAP header</source>
        <translation>Tambahkan header MBAP</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Add unit and CRC</source>
        <translation>Tambahkan unit dan CRC</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Add unit and LRC</source>
        <translation>Tambahkan unit dan LRC</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Complete</source>
        <translation>Lengkapi</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>Named requests: choose one to put its bytes in the editor</source>
        <translation>Permintaan bernama: pilih salah satu untuk menaruh byte-nya di editor</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Save as…</source>
        <translation>Simpan sebagai…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Keep the bytes in the editor under a name</source>
        <translation>Simpan byte di editor dengan sebuah nama</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Delete</source>
        <translation>Hapus</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Forget the chosen named request</source>
        <translation>Lupakan permintaan bernama yang dipilih</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>The bytes to send, as hex: 01 03 00 79 00 16 15 DD</source>
        <translation>Byte yang akan dikirim, sebagai hex: 01 03 00 79 00 16 15 DD</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>Sav&amp;ed:</source>
        <translation>Ters&amp;impan:</translation>
    </message>
    <message>
        <location line="+108"/>
        <source>not hex</source>
        <translation>bukan hex</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>1 byte</source>
        <translation>1 byte</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 bytes</source>
        <translation>%1 byte</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Type the request as hex, choose a saved one, or build it in the Form tab.</source>
        <translation>Ketik permintaan sebagai hex, pilih yang tersimpan, atau susun di tab Formulir.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>function %1 %2</source>
        <translation>fungsi %1 %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>CRC</source>
        <translation>CRC</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>LRC</source>
        <translation>LRC</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Not a whole %1 frame (%2). Send it as it is, or use “%3” if it is a PDU.</source>
        <translation>Bukan frame %1 yang utuh (%2). Kirim apa adanya, atau pakai “%3” jika ini PDU.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Unit %1 and a whole %2 request, but no CRC: use “Append CRC only” in the %3 menu, or send it as it is.</source>
        <translation>Unit %1 dan permintaan %2 yang utuh, tetapi tanpa CRC: pakai “Tambahkan CRC saja” di menu %3, atau kirim apa adanya.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 frame: unit %2, %3, %4 correct.</source>
        <translation>Frame %1: unit %2, %3, %4 benar.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 frame: unit %2, %3, %4 %5 is wrong (expected %6); it is sent as typed.</source>
        <translation>Frame %1: unit %2, %3, %4 %5 salah (seharusnya %6); dikirim sesuai ketikan.</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Not a whole MBAP frame (%1). Send it as it is, or use “%2” if it is a PDU.</source>
        <translation>Bukan frame MBAP yang utuh (%1). Kirim apa adanya, atau pakai “%2” jika ini PDU.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>MBAP frame: transaction %1, unit %2, %3, length %4%5.</source>
        <translation>Frame MBAP: transaksi %1, unit %2, %3, panjang %4%5.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source> (fits)</source>
        <translation> (sesuai)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source> (does not fit the bytes: sent as typed)</source>
        <translation> (tidak sesuai dengan byte-nya: dikirim sesuai ketikan)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Take the bytes as a PDU (function code first) and wrap them for this link, with the unit id of the connection bar; the added bytes are marked</source>
        <translation>Anggap byte sebagai PDU (kode fungsi lebih dulu) dan bungkus untuk link ini, dengan ID unit dari bilah koneksi; byte yang ditambahkan ditandai</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 (the bytes are a PDU)</source>
        <translation>%1 (byte-nya adalah PDU)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Append CRC only (the bytes are unit + PDU)</source>
        <translation>Tambahkan CRC saja (byte-nya adalah unit + PDU)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Add LRC and delimiters only (the bytes are unit + PDU)</source>
        <translation>Tambahkan LRC dan delimiter saja (byte-nya adalah unit + PDU)</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Added the MBAP header (transaction 1, protocol 0, length %1, unit %2) in front of the PDU.</source>
        <translation>Header MBAP (transaksi 1, protokol 0, panjang %1, unit %2) ditambahkan di depan PDU.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Added unit %1 in front and the CRC %2 at the end.</source>
        <translation>Unit %1 ditambahkan di depan dan CRC %2 di akhir.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Added &apos;:&apos; and unit %1 in front, and the LRC and CR LF at the end (as ASCII characters).</source>
        <translation>&apos;:&apos; dan unit %1 ditambahkan di depan, serta LRC dan CR LF di akhir (sebagai karakter ASCII).</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Appended the CRC %1.</source>
        <translation>CRC %1 ditambahkan di akhir.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Added &apos;:&apos; in front, and the LRC and CR LF at the end (as ASCII characters).</source>
        <translation>&apos;:&apos; ditambahkan di depan, serta LRC dan CR LF di akhir (sebagai karakter ASCII).</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>(choose a named request)</source>
        <translation>(pilih permintaan bernama)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Save request</source>
        <translation>Simpan permintaan</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Name of the request:</source>
        <translation>Nama permintaan:</translation>
    </message>
</context>
<context>
    <name>mbscope::RecordingControl</name>
    <message>
        <location filename="../../ui/session/recordingcontrol.cpp" line="+26"/>
        <source>it ends cleanly, at byte %1</source>
        <translation>berakhir dengan rapi di byte %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>it stops after the last complete batch, at byte %1; what was not written yet is not in it</source>
        <translation>berhenti setelah batch lengkap terakhir, di byte %1; yang belum sempat ditulis tidak ada di dalamnya</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the last batch was cut short at byte %1 and is left out</source>
        <translation>batch terakhir terpotong di byte %1 dan tidak disertakan</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the batch at byte %1 is damaged: it and all after it are left out</source>
        <translation>batch di byte %1 rusak: batch itu dan semua sesudahnya tidak disertakan</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>&lt;b&gt;Not recording any more&lt;/b&gt;: %1.</source>
        <translation>&lt;b&gt;Tidak merekam lagi&lt;/b&gt;: %1.</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+2"/>
        <source>Not recording: %1</source>
        <translation>Tidak merekam: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Recording to %1</source>
        <translation>Merekam ke %1</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>&lt;b&gt;mbscope stopped without closing its last recording&lt;/b&gt; (%1, %2). %3 requests came back, %4 frames in all: %5.</source>
        <translation>&lt;b&gt;mbscope berhenti tanpa menutup rekaman terakhirnya&lt;/b&gt; (%1, %2). %3 permintaan kembali, %4 frame seluruhnya: %5.</translation>
    </message>
    <message numerus="yes">
        <location line="+6"/>
        <source> %n older recording(s) were also left open.</source>
        <translation>
            <numerusform> %n rekaman lama juga tertinggal terbuka.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Open it in the traffic list</source>
        <translation>Buka di daftar lalu lintas</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Keep it in the capture folder</source>
        <translation>Simpan di folder capture</translation>
    </message>
    <message>
        <location line="+64"/>
        <source>The session was saved without its traffic: %1</source>
        <translation>Sesi disimpan tanpa lalu lintasnya: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Traffic so far copied to %1; what comes next is recorded in %2</source>
        <translation>Lalu lintas sejauh ini disalin ke %1; yang berikutnya direkam di %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Traffic recorded beside the session: %1</source>
        <translation>Lalu lintas direkam di samping sesi: %1</translation>
    </message>
</context>
<context>
    <name>mbscope::RegisterTable</name>
    <message>
        <location filename="../../ui/registers/registertable.cpp" line="+40"/>
        <source>AB (high byte first)</source>
        <translation>AB (byte atas dulu)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>BA (byte swap)</source>
        <translation>BA (tukar byte)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 (big endian)</source>
        <translation>%1 (big endian)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (word swap)</source>
        <translation>%1 (tukar word)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (byte swap)</source>
        <translation>%1 (tukar byte)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (little endian)</source>
        <translation>%1 (little endian)</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>Write requested: %1</source>
        <translation>Penulisan diminta: %1</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>What the registers of the current value column stand for</source>
        <translation>Arti register pada kolom nilai saat ini</translation>
    </message>
    <message>
        <location line="+5"/>
        <source> Order </source>
        <translation> Urutan </translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Word and byte order of the current value column: the order the value&apos;s bytes travel in, most significant named A</source>
        <translation>Urutan word dan byte kolom nilai saat ini: urutan byte nilai saat dikirim, yang paling signifikan dinamai A</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>+ Column</source>
        <translation>+ Kolom</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Add a value column showing the same registers in another format</source>
        <translation>Tambahkan kolom nilai yang menampilkan register yang sama dalam format lain</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Column</source>
        <translation>Kolom</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remove the current value column</source>
        <translation>Hapus kolom nilai saat ini</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Write with </source>
        <translation>Tulis dengan </translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The function an edited value is written with</source>
        <translation>Fungsi yang dipakai untuk menulis nilai yang disunting</translation>
    </message>
    <message>
        <location line="+52"/>
        <source>Column %1 </source>
        <translation>Kolom %1 </translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Profile: %1</source>
        <translation>Profil: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Profile: none</source>
        <translation>Profil: tidak ada</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Names, scaling and units come from the device profile %1</source>
        <translation>Nama, skala dan satuan diambil dari profil perangkat %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No device profile: no names or scaling</source>
        <translation>Tanpa profil perangkat: tanpa nama atau skala</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>read-only (%1)</source>
        <translation>hanya-baca (%1)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>05 Write Single Coil</source>
        <translation>05 Tulis Satu Coil</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>0F Write Multiple Coils</source>
        <translation>0F Tulis Banyak Coil</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>06 or 10 by width</source>
        <translation>06 atau 10 sesuai lebar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>06 Write Single Register</source>
        <translation>06 Tulis Satu Register</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>10 Write Multiple Registers</source>
        <translation>10 Tulis Banyak Register</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>Column %1 format</source>
        <translation>Format kolom %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Order</source>
        <translation>Urutan</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Use this order in every column</source>
        <translation>Pakai urutan ini di semua kolom</translation>
    </message>
</context>
<context>
    <name>mbscope::RegisterTableModel</name>
    <message>
        <location filename="../../ui/registers/registertablemodel.cpp" line="+21"/>
        <source>%1, %2 (%3)</source>
        <translation>%1, %2 (%3)</translation>
    </message>
    <message>
        <location line="+22"/>
        <location line="+20"/>
        <source>answer not shown: %1</source>
        <translation>jawaban tidak ditampilkan: %1</translation>
    </message>
    <message>
        <location line="-7"/>
        <source>answer not shown: the transaction ended with %1</source>
        <translation>jawaban tidak ditampilkan: transaksi berakhir dengan %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>answer not shown: the transaction ended with %1: %2</source>
        <translation>jawaban tidak ditampilkan: transaksi berakhir dengan %1: %2</translation>
    </message>
    <message>
        <location line="+192"/>
        <source>1  ON</source>
        <translation>1  ON</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>0  OFF</source>
        <translation>0  OFF</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>↑ %1 from %2</source>
        <translation>↑ %1 dari %2</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Register %1 is register %2 of the %3 registers of the %4 value at %5</source>
        <translation>Register %1 adalah register ke-%2 dari %3 register nilai %4 di %5</translation>
    </message>
    <message>
        <location line="-11"/>
        <location line="+65"/>
        <source>(%1 of %2 registers)</source>
        <translation>(%1 dari %2 register)</translation>
    </message>
    <message>
        <location line="-47"/>
        <source>%1 needs %2 registers from %3; the answer begins %4 registers into it</source>
        <translation>%1 memerlukan %2 register mulai %3; jawaban baru dimulai %4 register di dalamnya</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 needs %2 registers from %3; the answer ends after %4</source>
        <translation>%1 memerlukan %2 register mulai %3; jawaban berakhir setelah %4</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 needs %2 registers from %3; the profile&apos;s next value begins after %4</source>
        <translation>%1 memerlukan %2 register mulai %3; nilai berikutnya di profil dimulai setelah %4</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1 registers %2-%3</source>
        <translation>%1 register %2-%3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1
%2, on the wire %3</source>
        <translation>%1
%2, di jalur %3</translation>
    </message>
    <message>
        <location line="+8"/>
        <source> (register %1 of %2)</source>
        <translation> (register %1 dari %2)</translation>
    </message>
    <message>
        <location line="+54"/>
        <source>The profile names no value at this address</source>
        <translation>Profil tidak menamai nilai apa pun di alamat ini</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 as %2, value = raw × %3 + %4</source>
        <translation>%1 sebagai %2, nilai = mentah × %3 + %4</translation>
    </message>
    <message>
        <location line="+91"/>
        <source>PDU address</source>
        <translation>Alamat PDU</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Modicon (%1xxxx, from 1)</source>
        <translation>Modicon (%1xxxx, mulai 1)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Name</source>
        <translation>Nama</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Value</source>
        <translation>Nilai</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Scaled</source>
        <translation>Berskala</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The 0-based address the request carries (V1.1b3, 4.4)</source>
        <translation>Alamat berbasis 0 yang dibawa permintaan (V1.1b3, 4.4)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Modicon reference: the table digit %1, then the 1-based element number (PDU address + 1)</source>
        <translation>Referensi Modicon: digit tabel %1, lalu nomor elemen berbasis 1 (alamat PDU + 1)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Names from the profile %1</source>
        <translation>Nama dari profil %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>No profile: no names</source>
        <translation>Tanpa profil: tanpa nama</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1
Right-click to change the format</source>
        <translation>%1
Klik kanan untuk mengganti format</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The profile&apos;s format, scale, offset and unit: value = raw × scale + offset</source>
        <translation>Format, skala, offset dan satuan dari profil: nilai = mentah × skala + offset</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>%1: %2 are read-only; only coils and holding registers can be written</source>
        <translation>%1: %2 hanya-baca; hanya coil dan holding register yang bisa ditulis</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: this cell cannot be written (edit a value&apos;s first register)</source>
        <translation>%1: sel ini tidak bisa ditulis (sunting register pertama suatu nilai)</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>no cell to write</source>
        <translation>tidak ada sel untuk ditulis</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>not written: %1</source>
        <translation>tidak ditulis: %1</translation>
    </message>
</context>
<context>
    <name>mbscope::RegisterTrendPanel</name>
    <message>
        <location filename="../../ui/analysis/registertrendpanel.cpp" line="+63"/>
        <source>Add &amp;selected register</source>
        <translation>Tambahkan register yang &amp;dipilih</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Checked registers are plotted against time</source>
        <translation>Register yang dicentang diplot terhadap waktu</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Holding registers</source>
        <translation>Holding register</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Input registers</source>
        <translation>Input register</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Coils</source>
        <translation>Coil</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Discrete inputs</source>
        <translation>Discrete input</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&amp;Add</source>
        <translation>&amp;Tambah</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Plot the register at this address, read with this format</source>
        <translation>Plot register di alamat ini, dibaca dengan format ini</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Table:</source>
        <translation>Tabel:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Address:</source>
        <translation>Alamat:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Format:</source>
        <translation>Format:</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>A watch of the Watches tab</source>
        <translation>Sebuah pantauan dari tab Pantauan</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>One of the watch&apos;s values, by its point&apos;s name or its address</source>
        <translation>Salah satu nilai pantauan, menurut nama titiknya atau alamatnya</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Plot watch value</source>
        <translation>Gambar nilai pantauan</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Plot this value of the watch as the watch polls (Workspace → Start all)</source>
        <translation>Gambar nilai pantauan ini selama pantauan mem-polling (Daftar pantau → Mulai semua)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Watch:</source>
        <translation>Pantauan:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Value:</source>
        <translation>Nilai:</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>time since the first answer (s)</source>
        <translation>waktu sejak jawaban pertama (s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>scaled value</source>
        <translation>nilai berskala</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>t = %1 s</source>
        <translation>t = %1 s</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Keep every value in view as new answers arrive</source>
        <translation>Jaga semua nilai tetap terlihat saat jawaban baru masuk</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Forget the values plotted; the registers stay chosen</source>
        <translation>Lupakan nilai yang diplot; register tetap terpilih</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Plot the register selected in the Registers table, in the format of its column</source>
        <translation>Plot register yang dipilih di tabel Register, dalam format kolomnya</translation>
    </message>
    <message>
        <location line="+173"/>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>No register table to take a register from</source>
        <translation>Tidak ada tabel register untuk diambil register-nya</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Select a register in the Registers table first</source>
        <translation>Pilih dulu register di tabel Register</translation>
    </message>
    <message>
        <location line="+17"/>
        <location line="+27"/>
        <location line="+89"/>
        <source>Plotting %1</source>
        <translation>Memplot %1</translation>
    </message>
    <message>
        <location line="-108"/>
        <source>Not added: the address is wrong: %1</source>
        <translation>Tidak ditambahkan: alamatnya salah: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Not added: %1</source>
        <translation>Tidak ditambahkan: %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Not added: a %1 at PDU address %2 would go past the last address (65535)</source>
        <translation>Tidak ditambahkan: %1 di alamat PDU %2 akan melewati alamat terakhir (65535)</translation>
    </message>
    <message>
        <location line="+77"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>address %1</source>
        <translation>alamat %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Not added: choose a watch and one of its values</source>
        <translation>Tidak ditambahkan: pilih pantauan dan salah satu nilainya</translation>
    </message>
</context>
<context>
    <name>mbscope::RegisterWrite</name>
    <message>
        <location filename="../../ui/registers/registerwrite.cpp" line="+25"/>
        <source>%1: &apos;%2&apos; is not a coil value: expected 1 or 0 (on/off, true/false)</source>
        <translation>%1: &apos;%2&apos; bukan nilai coil: seharusnya 1 atau 0 (on/off, true/false)</translation>
    </message>
    <message>
        <location line="+12"/>
        <location line="+35"/>
        <source>%1, %2</source>
        <translation>%1, %2</translation>
    </message>
    <message>
        <location line="-12"/>
        <source>&apos;%1&apos; is not a number: the scaled value of %2 takes a decimal number</source>
        <translation>&apos;%1&apos; bukan angka: nilai berskala %2 harus berupa bilangan desimal</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 %2 (raw = (value - %3) / %4): %5</source>
        <translation>%1 %2 (mentah = (nilai - %3) / %4): %5</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>register %1 (PDU address %2)</source>
        <translation>register %1 (alamat PDU %2)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>coil %1 (PDU address %2)</source>
        <translation>coil %1 (alamat PDU %2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>discrete input %1 (PDU address %2)</source>
        <translation>discrete input %1 (alamat PDU %2)</translation>
    </message>
</context>
<context>
    <name>mbscope::ReplayController</name>
    <message>
        <location filename="../../ui/session/replaycontroller.cpp" line="+65"/>
        <source>A capture is still being read.</source>
        <translation>Capture masih dibaca.</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Stop the replay before opening another capture.</source>
        <translation>Hentikan putar ulang sebelum membuka capture lain.</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>%1 cannot be read: %2</source>
        <translation>%1 tidak dapat dibaca: %2</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 (%2): transactions %3, ok %4, failed %5</source>
        <translation>%1 (%2): transaksi %3, ok %4, gagal %5</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1; latency median %2 ms, p95 %3 ms, max %4 ms</source>
        <translation>%1; latensi median %2 ms, p95 %3 ms, maks %4 ms</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1. The file is damaged: %2; everything before it was read.</source>
        <translation>%1. Berkasnya rusak: %2; semua yang sebelumnya sudah dibaca.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1. No Modbus requests were found on the ports looked at: set the Modbus TCP and RTU ports.</source>
        <translation>%1. Tidak ada permintaan Modbus di port yang diperiksa: atur port Modbus TCP dan RTU.</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>A replay is already running.</source>
        <translation>Putar ulang sudah berjalan.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The capture is still being read.</source>
        <translation>Capture masih dibaca.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Open a capture or a session with recorded requests first.</source>
        <translation>Buka dulu capture atau sesi yang berisi permintaan terekam.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Connect to the device to replay to first.</source>
        <translation>Sambungkan dulu ke perangkat tujuan putar ulang.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stop the poll first: a replay sends one request at a time, as they were recorded.</source>
        <translation>Hentikan polling dulu: putar ulang mengirim satu permintaan per kali, sesuai rekamannya.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 is a delimited link: it carries no Modbus framing to replay into.</source>
        <translation>%1 adalah link berdelimiter: tidak membawa framing Modbus untuk diputar ulang.</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>The replay stopped: %1. %2</source>
        <translation>Putar ulang berhenti: %1. %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stopped after %1 of %2 requests. %3</source>
        <translation>Dihentikan setelah %1 dari %2 permintaan. %3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Writes not sent: %1 (%2).</source>
        <translation>Penulisan tidak dikirim: %1 (%2).</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Open a capture or a session with recorded answers first.</source>
        <translation>Buka dulu capture atau sesi yang berisi jawaban terekam.</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Not serving.</source>
        <translation>Tidak melayani.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Serving the recorded answers of %1 on %2 (distinct requests: %3). Answers served: %4, silences kept: %5, requests never recorded: %6.</source>
        <translation>Melayani jawaban terekam dari %1 di %2 (permintaan berbeda: %3). Jawaban dilayani: %4, diam dipertahankan: %5, permintaan tidak pernah terekam: %6.</translation>
    </message>
</context>
<context>
    <name>mbscope::ReplayDifferencesModel</name>
    <message>
        <location filename="../../ui/session/replaydifferencesmodel.cpp" line="+81"/>
        <source>the same</source>
        <translation>sama</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>values</source>
        <translation>nilai</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>bytes</source>
        <translation>byte</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>exception</source>
        <translation>pengecualian</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>outcome</source>
        <translation>hasil</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>timeout</source>
        <translation>waktu habis</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>latency</source>
        <translation>latensi</translation>
    </message>
    <message>
        <location line="+65"/>
        <source>No answers replayed yet.</source>
        <translation>Belum ada jawaban yang diputar ulang.</translation>
    </message>
    <message>
        <location line="-3"/>
        <source>%1: %2</source>
        <comment>what differs: how many</comment>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Answers replayed: %1, differing: %2 (%3).</source>
        <translation>Jawaban diputar ulang: %1, berbeda: %2 (%3).</translation>
    </message>
    <message>
        <location line="+68"/>
        <source>#</source>
        <translation>#</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Request</source>
        <translation>Permintaan</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Recorded answer</source>
        <translation>Jawaban terekam</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>New answer</source>
        <translation>Jawaban baru</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>What differs</source>
        <translation>Yang berbeda</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Differences</source>
        <translation>Perbedaan</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Recorded ms</source>
        <translation>ms terekam</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Now ms</source>
        <translation>ms sekarang</translation>
    </message>
</context>
<context>
    <name>mbscope::ReplayPanel</name>
    <message>
        <location filename="../../ui/session/replaypanel.cpp" line="+31"/>
        <source>Open a capture or a session</source>
        <translation>Buka capture atau sesi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Captures and sessions (*.pcap *.pcapng *.cap *.json *.journal);;All files (*)</source>
        <translation>Capture dan sesi (*.pcap *.pcapng *.cap *.json *.journal);;Semua berkas (*)</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Replaying the recorded requests to the target (%1 in all)…</source>
        <translation>Memutar ulang permintaan terekam ke target (%1 seluruhnya)…</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Open capture…</source>
        <translation>Buka capture…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A pcap or pcapng capture, a traffic journal, or a session document with captured traffic</source>
        <translation>Capture pcap atau pcapng, jurnal lalu lintas, atau dokumen sesi yang berisi lalu lintas terekam</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No recording opened.</source>
        <translation>Belum ada rekaman yang dibuka.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Server ports carrying Modbus TCP or Modbus UDP in a capture, separated by commas</source>
        <translation>Port server yang membawa Modbus TCP atau Modbus UDP di capture, dipisahkan koma</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>e.g. 4001</source>
        <translation>mis. 4001</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Server ports carrying RTU frames over TCP or UDP in a capture (a serial device server)</source>
        <translation>Port server yang membawa frame RTU lewat TCP atau UDP di capture (serial device server)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Modbus TCP ports</source>
        <translation>Port Modbus TCP</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>RTU ports</source>
        <translation>Port RTU</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>As recorded</source>
        <translation>Sesuai rekaman</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>2 times faster</source>
        <translation>2 kali lebih cepat</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>10 times faster</source>
        <translation>10 kali lebih cepat</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Back to back</source>
        <translation>Tanpa jeda</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Replay to the target</source>
        <translation>Putar ulang ke target</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Send the recorded requests to the connected device and compare each answer with the recorded one</source>
        <translation>Kirim permintaan terekam ke perangkat yang tersambung dan bandingkan setiap jawaban dengan jawaban terekam</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stop</source>
        <translation>Hentikan</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Show matching answers</source>
        <translation>Tampilkan jawaban yang sama</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Speed</source>
        <translation>Kecepatan</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>Where the recording answers as a device: tcp://, rtu-tcp://, udp://, rtu://… (port 0: any free port)</source>
        <translation>Tempat rekaman menjawab sebagai perangkat: tcp://, rtu-tcp://, udp://, rtu://… (port 0: port bebas mana saja)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Answer other requests with exception 0B</source>
        <translation>Jawab permintaan lain dengan pengecualian 0B</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Leave other requests unanswered</source>
        <translation>Biarkan permintaan lain tidak dijawab</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+113"/>
        <source>Serve</source>
        <translation>Layani</translation>
    </message>
    <message>
        <location line="-112"/>
        <source>Answer with the recorded answers on this endpoint, matched by unit and request</source>
        <translation>Jawab dengan jawaban terekam di endpoint ini, dicocokkan menurut unit dan permintaan</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Serve on</source>
        <translation>Layani di</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>Modbus TCP ports: %1</source>
        <translation>Port Modbus TCP: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>RTU ports: %1</source>
        <translation>Port RTU: %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Reading %1…</source>
        <translation>Membaca %1…</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Send the recorded writes?</source>
        <translation>Kirim penulisan yang terekam?</translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>The recording holds %n write(s) to the device: %1.</source>
        <translation>
            <numerusform>Rekaman berisi %n penulisan ke perangkat: %1.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Sending them changes the device again as they changed it when recorded (its outputs, its settings). Without them the other requests are replayed and the writes are listed as not sent.</source>
        <translation>Mengirimnya mengubah perangkat lagi seperti saat direkam (keluarannya, pengaturannya). Tanpanya, permintaan lain diputar ulang dan penulisan dicantumkan sebagai tidak dikirim.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Send the writes</source>
        <translation>Kirim penulisan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Replay without the writes</source>
        <translation>Putar ulang tanpa penulisan</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Replay not started.</source>
        <translation>Putar ulang tidak dimulai.</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Stopped serving.</source>
        <translation>Berhenti melayani.</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Stop serving</source>
        <translation>Berhenti melayani</translation>
    </message>
</context>
<context>
    <name>mbscope::ReplayServer</name>
    <message>
        <location filename="../../ui/session/replayserver.cpp" line="+51"/>
        <source>Cannot serve the recording on %1: %2</source>
        <translation>Tidak dapat melayani rekaman di %1: %2</translation>
    </message>
</context>
<context>
    <name>mbscope::RequestComposer</name>
    <message>
        <location filename="../../ui/compose/requestcomposer.cpp" line="+46"/>
        <source>&amp;Send</source>
        <translation>&amp;Kirim</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+12"/>
        <location line="+315"/>
        <source>Send the request once (Ctrl+Return)</source>
        <translation>Kirim permintaan sekali (Ctrl+Return)</translation>
    </message>
    <message>
        <location line="-324"/>
        <location line="+35"/>
        <location line="+260"/>
        <location line="+1"/>
        <source>Start &amp;poll</source>
        <translation>Mulai pollin&amp;g</translation>
    </message>
    <message>
        <location line="-308"/>
        <source>Ra&amp;w</source>
        <translation>Menta&amp;h</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Form</source>
        <translation>Formulir</translation>
    </message>
    <message>
        <location line="+18"/>
        <location line="+7"/>
        <source>Se&amp;nd  (Ctrl+Return)</source>
        <translation>Ki&amp;rim  (Ctrl+Return)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>back to back</source>
        <translation>tanpa jeda</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>From the start of one request to the start of the next; 0: as fast as the device answers</source>
        <translation>Dari awal satu permintaan ke awal permintaan berikutnya; 0: secepat perangkat menjawab</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>until stopped</source>
        <translation>sampai dihentikan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source> times</source>
        <translation> kali</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+290"/>
        <source>Send the request repeatedly (Ctrl+Shift+Return starts and stops)</source>
        <translation>Kirim permintaan berulang-ulang (Ctrl+Shift+Return memulai dan menghentikan)</translation>
    </message>
    <message>
        <location line="-283"/>
        <source>Poll</source>
        <translation>Polling</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Ever&amp;y</source>
        <translation>S&amp;etiap</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Count</source>
        <translation>Jumlah</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Convert</source>
        <translation>Ubah</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Keep as typed</source>
        <translation>Biarkan seperti diketik</translation>
    </message>
    <message>
        <location line="+77"/>
        <source>&amp;Request</source>
        <translation>&amp;Permintaan</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Edit raw bytes</source>
        <translation>&amp;Sunting byte mentah</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Build with the &amp;form</source>
        <translation>Susun dengan &amp;formulir</translation>
    </message>
    <message>
        <location line="+58"/>
        <source>remove the check sum, add an MBAP header</source>
        <translation>buang checksum, tambahkan header MBAP</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>remove the MBAP header, add the check sum</source>
        <translation>buang header MBAP, tambahkan checksum</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the same unit and PDU in the new framing</source>
        <translation>unit dan PDU yang sama dalam framing baru</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&lt;b&gt;The Raw bytes are a %1 frame; the link now takes %2 frames.&lt;/b&gt; Sent as they are, the device would misread them. Convert (%3) sends:&lt;br&gt;&lt;code&gt;%4&lt;/code&gt;</source>
        <translation>&lt;b&gt;Byte Mentah adalah frame %1; link sekarang memakai frame %2.&lt;/b&gt; Jika dikirim apa adanya, perangkat akan salah membacanya. Ubah (%3) mengirim:&lt;br&gt;&lt;code&gt;%4&lt;/code&gt;</translation>
    </message>
    <message>
        <location line="+80"/>
        <location line="+1"/>
        <source>Stop &amp;poll</source>
        <translation>Hentikan pollin&amp;g</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>The link is listen-only: it monitors the bus and never sends. Disconnect and untick Listen to send.</source>
        <translation>Tautan ini hanya mendengar: ia memantau bus dan tidak pernah mengirim. Putuskan sambungan dan hapus centang Simak untuk mengirim.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The window is a tap: the masters send through it. Press Disconnect to stop the tap and send from here.</source>
        <translation>Jendela ini adalah sadapan: master mengirim melaluinya. Tekan Putuskan untuk menghentikan sadapan dan mengirim dari sini.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Tap: Send and Poll are off; the masters&apos; requests go through the tap.</source>
        <translation>Sadap: Kirim dan Polling nonaktif; permintaan master lewat sadapan.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Listen only: Send and Poll are off, nothing is sent to the bus.</source>
        <translation>Hanya dengar: Kirim dan Polling nonaktif, tidak ada yang dikirim ke bus.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Connect first (connection bar above).</source>
        <translation>Sambungkan dulu (bilah koneksi di atas).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Convert the bytes for the new link, or keep them as typed.</source>
        <translation>Ubah byte untuk link baru, atau biarkan seperti diketik.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Type a request (Raw) or build one (Form).</source>
        <translation>Ketik permintaan (Mentah) atau susun (Formulir).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Polling…</source>
        <translation>Polling…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>1 byte ready.</source>
        <translation>1 byte siap.</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 bytes ready.</source>
        <translation>%1 byte siap.</translation>
    </message>
    <message>
        <location line="-6"/>
        <source>The form refuses this request: the reason is under the fields.</source>
        <translation>Formulir menolak permintaan ini: alasannya ada di bawah kolom isian.</translation>
    </message>
</context>
<context>
    <name>mbscope::RequestForm</name>
    <message>
        <location filename="../../ui/compose/requestformlayout.cpp" line="+47"/>
        <source>Read Device Identification</source>
        <translation>Baca Identifikasi Perangkat</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>ON (FF 00); unchecked: OFF (00 00)</source>
        <translation>ON (FF 00); tidak dicentang: OFF (00 00)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source> registers (1-121)</source>
        <translation> register (1-121)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Address</source>
        <translation>Alamat</translation>
    </message>
    <message>
        <location filename="../../ui/compose/requestform.cpp" line="+157"/>
        <location filename="../../ui/compose/requestformlayout.cpp" line="+0"/>
        <source>Value</source>
        <translation>Nilai</translation>
    </message>
    <message>
        <location filename="../../ui/compose/requestformlayout.cpp" line="+5"/>
        <source>Register values: decimal (0-65535 or -32768..-1) or hex (0x1234); coils: tick for ON</source>
        <translation>Nilai register: desimal (0-65535 atau -32768..-1) atau hex (0x1234); coil: centang untuk ON</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>01 basic (stream)</source>
        <translation>01 dasar (stream)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>02 regular (stream)</source>
        <translation>02 reguler (stream)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>03 extended (stream)</source>
        <translation>03 diperluas (stream)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>04 one object</source>
        <translation>04 satu objek</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>&amp;Function:</source>
        <translation>&amp;Fungsi:</translation>
    </message>
    <message>
        <location filename="../../ui/compose/requestform.cpp" line="-15"/>
        <location filename="../../ui/compose/requestformlayout.cpp" line="+1"/>
        <source>&amp;Address:</source>
        <translation>&amp;Alamat:</translation>
    </message>
    <message>
        <location line="+8"/>
        <location filename="../../ui/compose/requestformlayout.cpp" line="+1"/>
        <source>&amp;Quantity:</source>
        <translation>&amp;Jumlah:</translation>
    </message>
    <message>
        <location filename="../../ui/compose/requestformlayout.cpp" line="+1"/>
        <source>Coil &amp;value:</source>
        <translation>&amp;Nilai coil:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Value:</source>
        <translation>&amp;Nilai:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>AND mask:</source>
        <translation>Mask AND:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>OR mask:</source>
        <translation>Mask OR:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Write address:</source>
        <translation>Alamat &amp;tulis:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write q&amp;uantity:</source>
        <translation>J&amp;umlah tulis:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Read &amp;code:</source>
        <translation>&amp;Kode baca:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Object id:</source>
        <translation>ID &amp;objek:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Values:</source>
        <translation>Nilai:</translation>
    </message>
    <message>
        <location filename="../../ui/compose/requestform.cpp" line="+126"/>
        <location filename="../../ui/compose/requestformlayout.cpp" line="+33"/>
        <source>ON</source>
        <translation>ON</translation>
    </message>
    <message>
        <location line="-69"/>
        <location line="+69"/>
        <location filename="../../ui/compose/requestformlayout.cpp" line="+0"/>
        <source>OFF</source>
        <translation>OFF</translation>
    </message>
    <message>
        <location line="-136"/>
        <source>Start &amp;address:</source>
        <translation>&amp;Alamat awal:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Read &amp;address:</source>
        <translation>&amp;Alamat baca:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>FIFO pointer &amp;address:</source>
        <translation>&amp;Alamat pointer FIFO:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Read &amp;quantity:</source>
        <translation>&amp;Jumlah baca:</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>1-%1 %2 (V1.1b3)</source>
        <translation>1-%1 %2 (V1.1b3)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Coil</source>
        <translation>Coil</translation>
    </message>
    <message>
        <location line="+85"/>
        <source>value in row %1: &apos;%2&apos; is not a register value (0-65535, -32768..-1 or 0x0000-0xFFFF)</source>
        <translation>nilai di baris %1: &apos;%2&apos; bukan nilai register (0-65535, -32768..-1 atau 0x0000-0xFFFF)</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>address: %1</source>
        <translation>alamat: %1</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>AND mask &apos;%1&apos; is not a 16-bit hex value (0x0000-0xFFFF)</source>
        <translation>Mask AND &apos;%1&apos; bukan nilai hex 16-bit (0x0000-0xFFFF)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>OR mask &apos;%1&apos; is not a 16-bit hex value (0x0000-0xFFFF)</source>
        <translation>Mask OR &apos;%1&apos; bukan nilai hex 16-bit (0x0000-0xFFFF)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>write address: %1</source>
        <translation>alamat tulis: %1</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>function %1 has no form</source>
        <translation>fungsi %1 tidak punya formulir</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>Bytes: %1  (%2, unit %3)</source>
        <translation>Byte: %1  (%2, unit %3)</translation>
    </message>
    <message>
        <location filename="../../ui/compose/requestformlayout.cpp" line="-89"/>
        <source>Register value: decimal (0-65535 or -32768..-1) or hex (0x1234)</source>
        <translation>Nilai register: desimal (0-65535 atau -32768..-1) atau hex (0x1234)</translation>
    </message>
    <message>
        <location filename="../../ui/compose/requestform.cpp" line="-208"/>
        <source>%1 %2 is refused: %3 takes 1-%4 %5 in one request (Modbus V1.1b3)</source>
        <translation>%1 %2 ditolak: %3 menerima 1-%4 %5 dalam satu permintaan (Modbus V1.1b3)</translation>
    </message>
    <message>
        <location line="+110"/>
        <source>read quantity</source>
        <translation>jumlah baca</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>quantity</source>
        <translation>jumlah</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>write quantity</source>
        <translation>jumlah tulis</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>value &apos;%1&apos; is not a register value (0-65535, -32768..-1 or 0x0000-0xFFFF)</source>
        <translation>nilai &apos;%1&apos; bukan nilai register (0-65535, -32768..-1 atau 0x0000-0xFFFF)</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>object id 0x%1 is refused: an object id is one byte, 0x00-0xFF</source>
        <translation>id objek 0x%1 ditolak: id objek berukuran satu byte, 0x00-0xFF</translation>
    </message>
</context>
<context>
    <name>mbscope::RulePalette</name>
    <message>
        <location filename="../../ui/watch/rulepalette.cpp" line="+73"/>
        <source>alarm</source>
        <translation>alarm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>warning</source>
        <translation>peringatan</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>info</source>
        <translation>info</translation>
    </message>
</context>
<context>
    <name>mbscope::SavedRequests</name>
    <message>
        <location filename="../../ui/compose/savedrequests.cpp" line="+21"/>
        <source>RosRao read</source>
        <translation>Baca RosRao</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Read 10 holding registers from 0 (RTU, unit 1)</source>
        <translation>Baca 10 holding register mulai 0 (RTU, unit 1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Read 16 coils from 0 (RTU, unit 1)</source>
        <translation>Baca 16 coil mulai 0 (RTU, unit 1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Read 10 holding registers from 0 (TCP, unit 1)</source>
        <translation>Baca 10 holding register mulai 0 (TCP, unit 1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Report server id (RTU, unit 1)</source>
        <translation>Laporkan ID server (RTU, unit 1)</translation>
    </message>
</context>
<context>
    <name>mbscope::ScanDialog</name>
    <message>
        <location filename="../../ui/discovery/scandialog.cpp" line="+48"/>
        <location line="+1"/>
        <source> ms</source>
        <translation> md</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Start</source>
        <translation>&amp;Mulai</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sto&amp;p</source>
        <translation>&amp;Hentikan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Copy as watches (JSON)</source>
        <translation>&amp;Salin sebagai pantauan (JSON)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Add as watches</source>
        <translation>&amp;Tambahkan sebagai pantauan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Map unit…</source>
        <translation>&amp;Petakan unit…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Timi&amp;ng…</source>
        <translation>Ukur wa&amp;ktu…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Seria&amp;l settings…</source>
        <translation>Pengaturan seria&amp;l…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Record in pr&amp;ofile…</source>
        <translation>Catat di pr&amp;ofil…</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Scan for units</source>
        <translation>Pindai unit</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The link to scan. The scan opens a connection of its own; the window&apos;s connection is left alone.</source>
        <translation>Link yang dipindai. Pemindaian membuka koneksinya sendiri; koneksi jendela tidak diganggu.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Every id is asked this read: a scan never writes.</source>
        <translation>Setiap id ditanyai pembacaan ini: pemindaian tidak pernah menulis.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>1-247 on a serial line or a serial device server; 0 and 248-255 only over Modbus TCP.</source>
        <translation>1-247 pada jalur serial atau server perangkat serial; 0 dan 248-255 hanya lewat Modbus TCP.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>How long each id may take to answer.</source>
        <translation>Berapa lama setiap id boleh menjawab.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Quiet time between one answer (or timeout) and the next request.</source>
        <translation>Waktu hening antara satu jawaban (atau batas waktu) dan permintaan berikutnya.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>to</source>
        <translation>sampai</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>address</source>
        <translation>alamat</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>quantity</source>
        <translation>jumlah</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>gap</source>
        <translation>jeda</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Target:</source>
        <translation>Tu&amp;juan:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Unit ids:</source>
        <translation>Id &amp;unit:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Read:</source>
        <translation>&amp;Baca:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>T&amp;imeout:</source>
        <translation>Batas &amp;waktu:</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Watch definitions of the selected found units (or of every found unit) as JSON on the clipboard.</source>
        <translation>Definisi pantauan unit terpilih yang ditemukan (atau semua unit yang ditemukan) sebagai JSON di papan klip.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Add watches of the selected found units (or of every found unit) to the window&apos;s watches.</source>
        <translation>Tambahkan pantauan unit terpilih yang ditemukan (atau semua unit yang ditemukan) ke pantauan jendela.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Find which addresses the selected unit has, the largest read it takes and its optional functions; save the map as a profile the simulator serves.</source>
        <translation>Temukan alamat yang dimiliki unit terpilih, baca terbesar yang diterimanya, dan fungsi opsionalnya; simpan peta sebagai profil yang dilayani simulator.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Measure how the selected unit copes with being asked: the shortest gap between requests, pipelining, clients at once, the largest read; with the settings that follow.</source>
        <translation>Ukur ketahanan unit terpilih saat ditanya: jeda terpendek antarpermintaan, pipelining, klien sekaligus, baca terbesar; beserta pengaturan yang disarankan.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>On a serial port: try baud rates, parities and stop bits with the read above until a unit answers.</source>
        <translation>Pada port serial: coba laju baud, paritas, dan bit stop dengan baca di atas sampai sebuah unit menjawab.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Add the units that answered to an existing device profile, and its unknownUnit from what the other ids got (as scan --units --profile-out).</source>
        <translation>Tambahkan unit yang menjawab ke profil perangkat yang sudah ada, beserta unknownUnit-nya dari apa yang didapat id lain (seperti scan --units --profile-out).</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>Asks every id the read above, one at a time, and says what each did.</source>
        <translation>Menanyai setiap id dengan pembacaan di atas, satu per satu, dan menyebutkan apa yang dilakukan masing-masing.</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Give the link to scan, e.g. tcp://192.168.1.10:502.</source>
        <translation>Berikan link yang akan dipindai, mis. tcp://192.168.1.10:502.</translation>
    </message>
    <message>
        <location line="+52"/>
        <source>%1 of %2 ids asked, %3 found</source>
        <translation>%1 dari %2 id ditanyai, %3 ditemukan</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Scan complete</source>
        <translation>Pemindaian selesai</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stopped</source>
        <translation>Dihentikan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Time limit reached</source>
        <translation>Batas waktu tercapai</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Request limit reached</source>
        <translation>Batas permintaan tercapai</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The link failed: %1</source>
        <translation>Link gagal: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: %2 of %3 ids asked in %4, %5 found.</source>
        <translation>%1: %2 dari %3 id ditanyai dalam %4, %5 ditemukan.</translation>
    </message>
    <message numerus="yes">
        <location line="+141"/>
        <source>%n watch definition(s) copied to the clipboard.</source>
        <translation>
            <numerusform>%n definisi pantauan disalin ke papan klip.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Record units in profile</source>
        <translation>Catat unit di profil</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Device profiles (*.json)</source>
        <translation>Profil perangkat (*.json)</translation>
    </message>
</context>
<context>
    <name>mbscope::ScanResultModel</name>
    <message>
        <location filename="../../ui/discovery/scanresultmodel.cpp" line="+36"/>
        <source>answers</source>
        <translation>menjawab</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>exception</source>
        <translation>eksepsi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>gateway: no path (0A)</source>
        <translation>gateway: tidak ada jalur (0A)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>gateway: no answer behind it (0B)</source>
        <translation>gateway: tak ada jawaban di belakangnya (0B)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>silent</source>
        <translation>diam</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>answered with another id</source>
        <translation>menjawab dengan id lain</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>garbage</source>
        <translation>sampah</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>echo of the request</source>
        <translation>gema permintaan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>link error</source>
        <translation>galat link</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>exception %1: %2</source>
        <translation>eksepsi %1: %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the answer carried unit %1</source>
        <translation>jawaban membawa unit %1</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>%1 ms</source>
        <translation>%1 md</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Unit</source>
        <translation>Unit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Result</source>
        <translation>Hasil</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Latency</source>
        <translation>Latensi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Detail</source>
        <translation>Rincian</translation>
    </message>
</context>
<context>
    <name>mbscope::ScriptEditor</name>
    <message>
        <location filename="../../ui/sim/scripteditor.cpp" line="+44"/>
        <source>The script shown in the editor</source>
        <translation>Skrip yang ditampilkan di editor</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Save script</source>
        <translation>&amp;Simpan skrip</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Writes the script to its file (Ctrl+S); the simulator loads it again at once.</source>
        <translation>Menulis skrip ke berkasnya (Ctrl+S); simulator langsung memuatnya ulang.</translation>
    </message>
    <message>
        <location line="+62"/>
        <source>No script: the selected simulator&apos;s profile names none.</source>
        <translation>Tidak ada skrip: profil simulator yang dipilih tidak menyebut satu pun.</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Cannot read %1: %2</source>
        <translation>Tidak dapat membaca %1: %2</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 is part of mbscope: shown read-only.</source>
        <translation>%1 adalah bagian dari mbscope: ditampilkan hanya-baca.</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Not saved: cannot write %1: %2</source>
        <translation>Tidak disimpan: tidak dapat menulis %1: %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Not saved: writing %1 failed: %2</source>
        <translation>Tidak disimpan: penulisan %1 gagal: %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Saved %1; the simulator loads it again.</source>
        <translation>%1 disimpan; simulator memuatnya ulang.</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1 changed on disk; the editor keeps your edits (Save writes them over it).</source>
        <translation>%1 berubah di disk; editor mempertahankan suntingan Anda (Simpan menimpanya).</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1 loaded.</source>
        <translation>%1 dimuat.</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Line %1: %2</source>
        <translation>Baris %1: %2</translation>
    </message>
</context>
<context>
    <name>mbscope::SessionController</name>
    <message>
        <location filename="../../ui/session/sessioncontroller.cpp" line="+41"/>
        <source>Unsaved changes</source>
        <translation>Perubahan belum disimpan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The session %1 has changes that are not saved.</source>
        <translation>Sesi %1 punya perubahan yang belum disimpan.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Session not opened</source>
        <translation>Sesi tidak dibuka</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 was not opened; nothing was changed.</source>
        <translation>%1 tidak dibuka; tidak ada yang diubah.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>mbscope sessions (*.mbscope.json *.json);;All files (*)</source>
        <translation>Sesi mbscope (*.mbscope.json *.json);;Semua berkas (*)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save session</source>
        <translation>Simpan sesi</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Open session</source>
        <translation>Buka sesi</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>&amp;New session</source>
        <translation>Sesi ba&amp;ru</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Open session…</source>
        <translation>&amp;Buka sesi…</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Open &amp;recent</source>
        <translation>Buka yang &amp;terakhir</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Save session</source>
        <translation>&amp;Simpan sesi</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save session &amp;as…</source>
        <translation>Simpan sesi seb&amp;agai…</translation>
    </message>
    <message>
        <location line="+145"/>
        <source>line %1, column %2: %3</source>
        <translation>baris %1, kolom %2: %3</translation>
    </message>
    <message>
        <location line="+76"/>
        <source>(untitled)</source>
        <translation>(tanpa judul)</translation>
    </message>
    <message>
        <location line="+58"/>
        <source>untitled session%1 — mbscope</source>
        <translation>sesi tanpa judul%1 — mbscope</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1%2 — mbscope</source>
        <translation>%1%2 — mbscope</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>(none yet)</source>
        <translation>(belum ada)</translation>
    </message>
</context>
<context>
    <name>mbscope::SessionTools</name>
    <message>
        <location filename="../../ui/shell/sessiontools.cpp" line="+44"/>
        <source>Replay</source>
        <translation>Putar ulang</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Test plan</source>
        <translation>Rencana uji</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>&amp;Session</source>
        <translation>Se&amp;si</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Open capture for analysis and replay…</source>
        <translation>&amp;Buka capture untuk analisis dan putar ulang…</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Analyse the session&apos;s capture</source>
        <translation>&amp;Analisis capture sesi</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Replay to the target</source>
        <translation>&amp;Putar ulang ke target</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>S&amp;top the replay</source>
        <translation>&amp;Hentikan putar ulang</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ser&amp;ve the recorded answers</source>
        <translation>&amp;Layani jawaban terekam</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Run the test &amp;plan</source>
        <translation>&amp;Jalankan rencana uji</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Stop the test p&amp;lan</source>
        <translation>H&amp;entikan rencana uji</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>E&amp;xport test results as JUnit XML…</source>
        <translation>E&amp;kspor hasil uji sebagai JUnit XML…</translation>
    </message>
</context>
<context>
    <name>mbscope::SimFaultForm</name>
    <message>
        <location filename="../../ui/sim/simfaultform.cpp" line="+40"/>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Delay the answer</source>
        <translation>Tunda jawaban</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Drop the answer</source>
        <translation>Buang jawaban</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Wrong CRC or LRC</source>
        <translation>CRC atau LRC salah</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Exception instead of the answer</source>
        <translation>Pengecualian sebagai ganti jawaban</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Wrong transaction id (MBAP)</source>
        <translation>ID transaksi salah (MBAP)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Wrong unit id</source>
        <translation>ID unit salah</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fewer registers than asked</source>
        <translation>Register lebih sedikit dari yang diminta</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The answer in chunks</source>
        <translation>Jawaban dalam potongan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The answer a byte at a time</source>
        <translation>Jawaban byte demi byte</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Junk bytes around the answer</source>
        <translation>Byte sampah di sekitar jawaban</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The answer more than once</source>
        <translation>Jawaban lebih dari sekali</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Close the connection</source>
        <translation>Tutup sambungan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Line noise (flipped bits)</source>
        <translation>Derau saluran (bit terbalik)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Fault:</source>
        <translation>&amp;Gangguan:</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+378"/>
        <source>any unit</source>
        <translation>unit apa pun</translation>
    </message>
    <message>
        <location line="-377"/>
        <source>&amp;Unit:</source>
        <translation>&amp;Unit:</translation>
    </message>
    <message>
        <location line="+7"/>
        <location line="+371"/>
        <source>any function</source>
        <translation>fungsi apa pun</translation>
    </message>
    <message>
        <location line="-370"/>
        <source>Function &amp;code:</source>
        <translation>&amp;Kode fungsi:</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>any</source>
        <translation>semua</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Only requests that touch the addresses from here to &apos;to&apos; (any: every request).</source>
        <translation>Hanya permintaan yang menyentuh alamat dari sini sampai &apos;sampai&apos; (semua: setiap permintaan).</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>to</source>
        <translation>sampai</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Addresses:</source>
        <translation>Alamat:</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The share of matching answers the rule changes: 1 for every one, 0.1 for one in ten.</source>
        <translation>Porsi jawaban yang cocok yang diubah aturan ini: 1 untuk semuanya, 0.1 untuk satu dari sepuluh.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Probability:</source>
        <translation>&amp;Peluang:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>fixed</source>
        <translation>tetap</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>uniform</source>
        <translation>seragam</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>normal</source>
        <translation>normal</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>exponential</source>
        <translation>eksponensial</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>lognormal</source>
        <translation>log-normal</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Distribution:</source>
        <translation>&amp;Distribusi:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Delay:</source>
        <translation>Tunda:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Mean:</source>
        <translation>Rata-rata:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Standard deviation:</source>
        <translation>Simpangan baku:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>At least:</source>
        <translation>Minimal:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>At most:</source>
        <translation>Maksimal:</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>01 illegal function, 02 illegal data address, 03 illegal data value, 04 server device failure, 06 server device busy, 0B gateway target failed to respond.</source>
        <translation>01 fungsi tidak sah, 02 alamat data tidak sah, 03 nilai data tidak sah, 04 kegagalan perangkat server, 06 perangkat server sibuk, 0B perangkat tujuan gateway tidak menjawab.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>E&amp;xception code:</source>
        <translation>Kode e&amp;xception:</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Added to the transaction id (modulo 65536) or the unit id (modulo 256)</source>
        <translation>Ditambahkan ke ID transaksi (modulo 65536) atau ID unit (modulo 256)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Added to the id:</source>
        <translation>Ditambahkan ke ID:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Registers (or bytes of coils) left out of a read&apos;s answer</source>
        <translation>Register (atau byte coil) yang dihilangkan dari jawaban baca</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fewer by:</source>
        <translation>Kurang sebanyak:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Bytes per chunk:</source>
        <translation>Byte per potongan:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Between chunks, bytes or copies of the answer</source>
        <translation>Di antara potongan, byte atau salinan jawaban</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gap:</source>
        <translation>Jeda:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Random bytes before:</source>
        <translation>Byte acak sebelum:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Random bytes after:</source>
        <translation>Byte acak sesudah:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Extra copies:</source>
        <translation>Salinan tambahan:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>before the answer</source>
        <translation>sebelum jawaban</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>midway through the answer</source>
        <translation>di tengah jawaban</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>after the answer</source>
        <translation>sesudah jawaban</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Close:</source>
        <translation>Tutup:</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Each bit of a request or answer flips with this probability: a request hit is lost, an answer hit fails its CRC or LRC.</source>
        <translation>Setiap bit permintaan atau jawaban terbalik dengan peluang ini: permintaan yang terkena hilang, jawaban yang terkena gagal CRC atau LRC-nya.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Bit error rate:</source>
        <translation>Laju galat bit:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Add rule</source>
        <translation>&amp;Tambah aturan</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Adds the rule to those in force: the simulator&apos;s next request sees it.</source>
        <translation>Menambahkan aturan ke aturan yang berlaku: permintaan berikutnya ke simulator sudah terkena.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Rules in force:</source>
        <translation>Aturan yang berlaku:</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Remove</source>
        <translation>&amp;Hapus</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;No faults</source>
        <translation>Tanpa ga&amp;ngguan</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Removes every rule: correct answers from the next request on.</source>
        <translation>Menghapus semua aturan: jawaban benar mulai permintaan berikutnya.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Load rules file...</source>
        <translation>&amp;Muat berkas aturan...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Replaces the rules by those of a faults file (the format of mbscope simulate --faults).</source>
        <translation>Mengganti aturan dengan isi berkas gangguan (format mbscope simulate --faults).</translation>
    </message>
    <message>
        <location line="+101"/>
        <source>Not added: a uniform delay needs &apos;At most&apos; (%1 ms) at or above &apos;At least&apos; (%2 ms).</source>
        <translation>Tidak ditambahkan: tunda seragam memerlukan &apos;Maksimal&apos; (%1 ms) sama dengan atau di atas &apos;Minimal&apos; (%2 ms).</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Not added: the address range ends (%1) before it starts (%2).</source>
        <translation>Tidak ditambahkan: rentang alamat berakhir (%1) sebelum dimulai (%2).</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Not added: junk needs random bytes before or after the answer.</source>
        <translation>Tidak ditambahkan: sampah memerlukan byte acak sebelum atau sesudah jawaban.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Added: %1.</source>
        <translation>Ditambahkan: %1.</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>No fault rules: the simulator answers correctly from the next request on.</source>
        <translation>Tanpa aturan gangguan: simulator menjawab dengan benar mulai permintaan berikutnya.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The rules file does not read; the rules in force stay:
%1</source>
        <translation>Berkas aturan tidak dapat dibaca; aturan yang berlaku tetap:
%1</translation>
    </message>
    <message numerus="yes">
        <location line="+4"/>
        <source>%n rule(s) from %1, seed %2.</source>
        <translation>
            <numerusform>%n aturan dari %1, seed %2.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Load fault rules</source>
        <translation>Muat aturan gangguan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fault rules (*.json);;All files (*)</source>
        <translation>Aturan gangguan (*.json);;Semua berkas (*)</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>(none: every answer is correct)</source>
        <translation>(tidak ada: setiap jawaban benar)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>delay %1 ms</source>
        <translation>tunda %1 ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>delay uniform %1 to %2 ms</source>
        <translation>tunda seragam %1 sampai %2 ms</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>delay normal, mean %1 ms, standard deviation %2 ms</source>
        <translation>tunda normal, rata-rata %1 ms, simpangan baku %2 ms</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>delay exponential, mean %1 ms</source>
        <translation>tunda eksponensial, rata-rata %1 ms</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>delay lognormal, mean %1 ms, standard deviation %2 ms</source>
        <translation>tunda log-normal, rata-rata %1 ms, simpangan baku %2 ms</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>drop the answer</source>
        <translation>buang jawaban</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>wrong CRC or LRC</source>
        <translation>CRC atau LRC salah</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>exception %1</source>
        <translation>pengecualian %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>transaction id + %1</source>
        <translation>ID transaksi + %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unit id + %1</source>
        <translation>ID unit + %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 fewer registers</source>
        <translation>%1 register lebih sedikit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>chunks of %1 bytes, %2 ms apart</source>
        <translation>potongan %1 byte, berjarak %2 ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a byte every %1 ms</source>
        <translation>satu byte setiap %1 ms</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>junk: %1 bytes before, %2 after</source>
        <translation>sampah: %1 byte sebelum, %2 sesudah</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 extra copies, %2 ms apart</source>
        <translation>%1 salinan tambahan, berjarak %2 ms</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>close before the answer</source>
        <translation>tutup sebelum jawaban</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>close midway through the answer</source>
        <translation>tutup di tengah jawaban</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>close after the answer</source>
        <translation>tutup sesudah jawaban</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>line noise, bit error rate %1</source>
        <translation>derau saluran, laju galat bit %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>line noise on requests, bit error rate %1</source>
        <translation>derau saluran pada permintaan, laju galat bit %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>line noise on answers, bit error rate %1</source>
        <translation>derau saluran pada jawaban, laju galat bit %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>unit %1</source>
        <translation>unit %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>function %1</source>
        <translation>fungsi %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 for %2, %3</source>
        <translation>%1 untuk %2, %3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1, addresses %2 to %3</source>
        <translation>%1, alamat %2 sampai %3</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1, starting at %2</source>
        <translation>%1, mulai di %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1, quantity %2</source>
        <translation>%1, jumlah %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1, writing %2</source>
        <translation>%1, menulis %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 (when the interval is under a turnaround of %2 ms on average)</source>
        <translation>%1 (bila selang di bawah waktu balik rata-rata %2 ms)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 (probability by interval, %2)</source>
        <translation>%1 (peluang menurut selang, %2)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 (probability %2)</source>
        <translation>%1 (peluang %2)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>mbscope::SimRegisterModel</name>
    <message>
        <location filename="../../ui/sim/simregistermodel.cpp" line="+102"/>
        <source>coil</source>
        <translation>coil</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>discrete input</source>
        <translation>discrete input</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>input register</source>
        <translation>input register</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>holding register</source>
        <translation>holding register</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1[%2]</source>
        <translation>%1[%2]</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1, register %2 of %3</source>
        <translation>%1, register %2 dari %3</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1 (unit: %2)</source>
        <translation>%1 (satuan: %2)</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1 (0x%2)</source>
        <translation>%1 (0x%2)</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Table</source>
        <translation>Tabel</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Address</source>
        <translation>Alamat</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Name</source>
        <translation>Nama</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Value</source>
        <translation>Nilai</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Hex</source>
        <translation>Hex</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>&apos;%1&apos; is not a bit value for %2 %3: type 0 or 1.</source>
        <translation>&apos;%1&apos; bukan nilai bit untuk %2 %3: ketik 0 atau 1.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&apos;%1&apos; is not a register value for %2 %3: type 0 to 65535, or 0x0000 to 0xFFFF.</source>
        <translation>&apos;%1&apos; bukan nilai register untuk %2 %3: ketik 0 sampai 65535, atau 0x0000 sampai 0xFFFF.</translation>
    </message>
</context>
<context>
    <name>mbscope::SimRunListModel</name>
    <message>
        <location filename="../../ui/sim/simrunlistmodel.cpp" line="+111"/>
        <source>%1 (built-in, first run)</source>
        <translation>%1 (bawaan, jalan pertama)</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Profile</source>
        <translation>Profil</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Listening on</source>
        <translation>Mendengarkan di</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Requests</source>
        <translation>Permintaan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Faulted</source>
        <translation>Diganggu</translation>
    </message>
</context>
<context>
    <name>mbscope::SimScriptPanel</name>
    <message>
        <location filename="../../ui/sim/simscriptpanel.cpp" line="+30"/>
        <source>Re&amp;load scripts</source>
        <translation>Muat &amp;ulang skrip</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Loads every script of this simulator again from its file, with fresh globals.</source>
        <translation>Memuat ulang setiap skrip simulator ini dari berkasnya, dengan variabel global yang baru.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Clear lo&amp;g</source>
        <translation>Bersihkan lo&amp;g</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>What the scripts write with log(...) or console.log(...), and their errors with file and line.</source>
        <translation>Apa yang ditulis skrip dengan log(...) atau console.log(...), serta galatnya dengan berkas dan baris.</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>%1  %2  error: %3</source>
        <translation>%1  %2  galat: %3</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>No simulator selected.</source>
        <translation>Tidak ada simulator yang dipilih.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>This simulator&apos;s profile names no script (docs/profiles.md, &quot;Scripts&quot;).</source>
        <translation>Profil simulator ini tidak menyebut skrip apa pun (docs/profiles.md, &quot;Scripts&quot;).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Scripts: %1</source>
        <translation>Skrip: %1</translation>
    </message>
</context>
<context>
    <name>mbscope::SimTrafficModel</name>
    <message>
        <location filename="../../ui/sim/simtrafficmodel.cpp" line="+110"/>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>no answer: dropped by fault rule %1</source>
        <translation>tanpa jawaban: dibuang oleh aturan gangguan %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>exception %1 (%2)</source>
        <translation>pengecualian %1 (%2)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>answered</source>
        <translation>dijawab</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no answer: %1</source>
        <translation>tanpa jawaban: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown unit: %1</source>
        <translation>unit tidak dikenal: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>checksum error: %1</source>
        <translation>error checksum: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>malformed: %1</source>
        <translation>cacat: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>garbage: %1</source>
        <translation>sampah: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>connection opened</source>
        <translation>koneksi dibuka</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>connection refused: %1</source>
        <translation>koneksi ditolak: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>connection closed: %1</source>
        <translation>koneksi ditutup: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1, changed by fault rule %2</source>
        <translation>%1, diubah oleh aturan gangguan %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1, then the connection closed</source>
        <translation>%1, lalu koneksi ditutup</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>%1; sent %2 ms after the request</source>
        <translation>%1; dikirim %2 ms setelah permintaan</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Time (s)</source>
        <translation>Waktu (s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Endpoint</source>
        <translation>Endpoint</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Peer</source>
        <translation>Klien</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Unit</source>
        <translation>Unit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Function</source>
        <translation>Fungsi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Outcome</source>
        <translation>Hasil</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Request</source>
        <translation>Permintaan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sent</source>
        <translation>Terkirim</translation>
    </message>
</context>
<context>
    <name>mbscope::SimulatorNotice</name>
    <message>
        <location filename="../../ui/shell/simulatornotice.cpp" line="+19"/>
        <source>&lt;b&gt;Connected to mbscope&apos;s built-in simulator&lt;/b&gt;, not to a device: a RosRao gamma detector (profile &lt;code&gt;%1&lt;/code&gt;) answering on &lt;code&gt;%2&lt;/code&gt;. Press &lt;b&gt;Send&lt;/b&gt; to read its 22 registers. To talk to a real device, press &lt;b&gt;Disconnect&lt;/b&gt;, choose its link type, host and port (or serial port) and press &lt;b&gt;Connect&lt;/b&gt;.</source>
        <translation>&lt;b&gt;Tersambung ke simulator bawaan mbscope&lt;/b&gt;, bukan ke perangkat: detektor gamma RosRao (profil &lt;code&gt;%1&lt;/code&gt;) yang menjawab di &lt;code&gt;%2&lt;/code&gt;. Tekan &lt;b&gt;Kirim&lt;/b&gt; untuk membaca 22 register-nya. Untuk berbicara dengan perangkat sungguhan, tekan &lt;b&gt;Putuskan&lt;/b&gt;, pilih jenis link, host dan port (atau port serial)-nya, lalu tekan &lt;b&gt;Sambungkan&lt;/b&gt;.</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>&lt;b&gt;Tap&lt;/b&gt; in front of the built-in simulator on &lt;code&gt;%1&lt;/code&gt;: point a master (mbpoll, a PLC, &lt;code&gt;mbscope read&lt;/code&gt;) at &lt;code&gt;%2&lt;/code&gt;; each request and its answer are listed twice in Traffic, the master&apos;s and the device&apos;s leg.</source>
        <translation>&lt;b&gt;Sadap&lt;/b&gt; di depan simulator bawaan di &lt;code&gt;%1&lt;/code&gt;: arahkan master (mbpoll, PLC, &lt;code&gt;mbscope read&lt;/code&gt;) ke &lt;code&gt;%2&lt;/code&gt;; setiap permintaan dan jawabannya tercantum dua kali di Lalu lintas, sisi master dan sisi perangkat.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Disconnected. The built-in simulator still answers on &lt;code&gt;%1&lt;/code&gt;: press &lt;b&gt;Connect&lt;/b&gt; to use it again, or choose a real device&apos;s link type, host and port (or serial port) first.</source>
        <translation>Terputus. Simulator bawaan masih menjawab di &lt;code&gt;%1&lt;/code&gt;: tekan &lt;b&gt;Sambungkan&lt;/b&gt; untuk memakainya lagi, atau pilih dulu jenis link, host dan port (atau port serial) perangkat sungguhan.</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>&lt;b&gt;Listening only&lt;/b&gt; to the built-in simulator on &lt;code&gt;%1&lt;/code&gt;: nothing is sent, and the simulator answers only requests, so the traffic stays empty unless another master polls it. Untick &lt;b&gt;Listen&lt;/b&gt; and press &lt;b&gt;Connect&lt;/b&gt; to send it requests.</source>
        <translation>&lt;b&gt;Hanya menyimak&lt;/b&gt; simulator bawaan di &lt;code&gt;%1&lt;/code&gt;: tidak ada yang dikirim, dan simulator hanya menjawab permintaan, jadi lalu lintas tetap kosong kecuali ada master lain yang mem-polling-nya. Hilangkan centang &lt;b&gt;Simak&lt;/b&gt; lalu tekan &lt;b&gt;Sambungkan&lt;/b&gt; untuk mengirim permintaan kepadanya.</translation>
    </message>
</context>
<context>
    <name>mbscope::SimulatorPanel</name>
    <message>
        <location filename="../../ui/sim/simulatorpanel.cpp" line="+48"/>
        <source>Modbus TCP</source>
        <translation>Modbus TCP</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RTU over TCP</source>
        <translation>RTU lewat TCP</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ASCII over TCP</source>
        <translation>ASCII lewat TCP</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Modbus UDP</source>
        <translation>Modbus UDP</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RTU over UDP</source>
        <translation>RTU lewat UDP</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Modbus TCP Security (TLS)</source>
        <translation>Modbus TCP Security (TLS)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Serial RTU</source>
        <translation>RTU serial</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Serial ASCII</source>
        <translation>ASCII serial</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>Profile:</source>
        <translation>Profil:</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>A built-in profile, or the path of a profile file (docs/profiles.md).</source>
        <translation>Profil bawaan, atau path berkas profil (docs/profiles.md).</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>...</source>
        <translation>...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Choose a profile file</source>
        <translation>Pilih berkas profil</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Listen on:</source>
        <translation>Dengarkan di:</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Where the simulator listens, as a URL: port 0 lets the system choose a free port.</source>
        <translation>Tempat simulator mendengarkan, sebagai URL: port 0 membiarkan sistem memilih port bebas.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Start</source>
        <translation>Mulai</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stop</source>
        <translation>Hentikan</translation>
    </message>
    <message>
        <location line="+55"/>
        <source>Registers</source>
        <translation>Register</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Faults</source>
        <translation>Gangguan</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>Traffic</source>
        <translation>Lalu lintas</translation>
    </message>
    <message>
        <location line="-87"/>
        <source>Stops the simulator selected in the list.</source>
        <translation>Menghentikan simulator yang dipilih di daftar.</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Unit:</source>
        <translation>Unit:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Double-click a value to set it in the simulator (decimal, or hex with 0x).</source>
        <translation>Klik ganda sebuah nilai untuk mengaturnya di simulator (desimal, atau hex dengan 0x).</translation>
    </message>
    <message>
        <location line="+48"/>
        <source>&amp;Clear</source>
        <translation>&amp;Kosongkan</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Script</source>
        <translation>Skrip</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Set %1 %2 of unit %3 to %4.</source>
        <translation>%1 %2 unit %3 diatur ke %4.</translation>
    </message>
    <message numerus="yes">
        <location line="+45"/>
        <source>%n line(s), the newest %1 kept.</source>
        <translation>
            <numerusform>%n baris, %1 terbaru disimpan.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>%n line(s); %1 older line(s) no longer shown (the newest %2 are kept).</source>
        <translation>
            <numerusform>%n baris; %1 baris lama tidak ditampilkan lagi (%2 terbaru disimpan).</numerusform>
        </translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Open a device profile</source>
        <translation>Buka profil perangkat</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Device profiles (*.json);;All files (*)</source>
        <translation>Profil perangkat (*.json);;Semua berkas (*)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Choose a profile first: a built-in one from the list, or a profile file.</source>
        <translation>Pilih profil dulu: profil bawaan dari daftar, atau berkas profil.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The profile &apos;%1&apos; cannot be loaded: %2</source>
        <translation>Profil &apos;%1&apos; tidak dapat dimuat: %2</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The simulator was not started on %1: %2</source>
        <translation>Simulator tidak dijalankan di %1: %2</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>saved fault rules</source>
        <translation>aturan gangguan tersimpan</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The fault rules saved at the last run do not read and were dropped: %1</source>
        <translation>Aturan gangguan yang disimpan pada jalannya terakhir tidak terbaca dan dibuang: %1</translation>
    </message>
    <message numerus="yes">
        <location line="+9"/>
        <source>%n fault rule(s) of the last run are in force again (Faults tab: No faults clears them).</source>
        <translation>
            <numerusform>%n aturan gangguan dari jalannya terakhir berlaku lagi (tab Gangguan: tombol Tanpa gangguan membersihkannya).</numerusform>
        </translation>
    </message>
    <message>
        <location line="+55"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>mbscope::SweepPanel</name>
    <message>
        <location filename="../../ui/analysis/sweeppanel.cpp" line="+43"/>
        <source>&amp;Start sweep</source>
        <translation>&amp;Mulai sapuan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>S&amp;top</source>
        <translation>&amp;Hentikan</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Poll intervals in milliseconds, separated by commas; each is run in turn</source>
        <translation>Interval polling dalam milidetik, dipisahkan koma; dijalankan bergiliran</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Transactions (poll cycles) at each interval</source>
        <translation>Transaksi (siklus polling) di setiap interval</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Intervals (ms):</source>
        <translation>Interval (ms):</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Count per interval:</source>
        <translation>Jumlah per interval:</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>poll interval (ms)</source>
        <translation>interval polling (ms)</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+5"/>
        <source>error rate (%)</source>
        <translation>tingkat error (%)</translation>
    </message>
    <message>
        <location line="-4"/>
        <source>latency (ms)</source>
        <translation>latensi (ms)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>median latency (ms)</source>
        <translation>latensi median (ms)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>p95 latency (ms)</source>
        <translation>latensi p95 (ms)</translation>
    </message>
    <message>
        <location line="+59"/>
        <source>interval %1 of %2 is empty: write milliseconds between the commas</source>
        <translation>interval %1 dari %2 kosong: tulis milidetik di antara koma</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>interval %1 (&apos;%2&apos;) is not a whole number of milliseconds from 0 to 3600000</source>
        <translation>interval %1 (&apos;%2&apos;) bukan bilangan bulat milidetik dari 0 sampai 3600000</translation>
    </message>
    <message>
        <location line="-14"/>
        <source>no intervals: write them in milliseconds, separated by commas (100, 200, 300)</source>
        <translation>tidak ada interval: tulis dalam milidetik, dipisahkan koma (100, 200, 300)</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>Not started: %1</source>
        <translation>Tidak dimulai: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Not started: connect to a device first</source>
        <translation>Tidak dimulai: sambungkan ke perangkat dulu</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Not started: a poll is running; stop it first</source>
        <translation>Tidak dimulai: polling sedang berjalan; hentikan dulu</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Not started: there is no request to send (write one in the request composer)</source>
        <translation>Tidak dimulai: tidak ada permintaan untuk dikirim (tulis di penyusun permintaan)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Not started: the link did not take the sweep</source>
        <translation>Tidak dimulai: link tidak menerima sapuan</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Sweeping %1 intervals, %2 transactions each</source>
        <translation>Menyapu %1 interval, masing-masing %2 transaksi</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Interval %1 ms (%2 of %3): cycle %4 of %5</source>
        <translation>Interval %1 ms (%2 dari %3): siklus %4 dari %5</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Sweep stopped: %1 of %2 intervals run</source>
        <translation>Sapuan dihentikan: %1 dari %2 interval dijalankan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sweep finished: %1 intervals</source>
        <translation>Sapuan selesai: %1 interval</translation>
    </message>
</context>
<context>
    <name>mbscope::SweepTableModel</name>
    <message>
        <location filename="../../ui/analysis/sweeptablemodel.cpp" line="+73"/>
        <source>Stopped before its count: the figures cover the part that ran</source>
        <translation>Dihentikan sebelum jumlahnya tercapai: angka mencakup bagian yang sudah berjalan</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 (stopped)</source>
        <translation>%1 (dihentikan)</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Interval (ms)</source>
        <translation>Interval (ms)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cycles</source>
        <translation>Siklus</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Transactions</source>
        <translation>Transaksi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Failed</source>
        <translation>Gagal</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Timeouts</source>
        <translation>Waktu habis</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Error rate (%)</source>
        <translation>Tingkat error (%)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Median (ms)</source>
        <translation>Median (ms)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>p95 (ms)</source>
        <translation>p95 (ms)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Max (ms)</source>
        <translation>Maks (ms)</translation>
    </message>
</context>
<context>
    <name>mbscope::TableCsv</name>
    <message>
        <location filename="../../ui/common/tablecsv.cpp" line="+54"/>
        <location line="+5"/>
        <source>cannot write %1: %2</source>
        <translation>tidak dapat menulis %1: %2</translation>
    </message>
</context>
<context>
    <name>mbscope::TapFields</name>
    <message>
        <location filename="../../ui/link/tapfields.cpp" line="+50"/>
        <source>tcp://0.0.0.0:502</source>
        <translation>tcp://0.0.0.0:502</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Where the masters (a SCADA, a PLC, mbpoll...) connect, as if to the device: one URL or several separated by spaces, tcp://, rtu-tcp://, udp://, tls:// or a serial port rtu:///dev/ttyUSB0?baud=19200&amp;parity=N (port 0: any free port)</source>
        <translation>Tempat master (SCADA, PLC, mbpoll...) tersambung, seolah ke perangkat: satu URL atau beberapa dipisah spasi, tcp://, rtu-tcp://, udp://, tls:// atau port serial rtu:///dev/ttyUSB0?baud=19200&amp;parity=N (port 0: port bebas mana pun)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>none: every unit to the target</source>
        <translation>tidak ada: setiap unit ke target</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Read-only</source>
        <translation>Hanya baca</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Forward no write (05, 06, 0F, 10, 15, 16, 17) and no Diagnostics sub-function that changes a device: refused and counted, so a tap on a production line cannot change a device by accident</source>
        <translation>Jangan teruskan penulisan (05, 06, 0F, 10, 15, 16, 17) maupun subfungsi Diagnostik yang mengubah perangkat: ditolak dan dihitung, agar sadapan di jalur produksi tidak dapat mengubah perangkat secara tidak sengaja</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>exception 01</source>
        <translation>eksepsi 01</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+7"/>
        <source>silence</source>
        <translation>diam</translation>
    </message>
    <message>
        <location line="-5"/>
        <source>What a refused write gets: exception 01 (illegal function) or no answer</source>
        <translation>Yang diterima penulisan yang ditolak: eksepsi 01 (fungsi ilegal) atau tanpa jawaban</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>auto</source>
        <translation>otomatis</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>exception 0B/0A</source>
        <translation>eksepsi 0B/0A</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>What a master gets when its device does not answer (exception 0B) or no route serves its unit (exception 0A): auto gives exceptions to Modbus/TCP and UDP masters and silence to serial ones</source>
        <translation>Yang diterima master bila perangkatnya tidak menjawab (eksepsi 0B) atau tidak ada rute yang melayani unitnya (eksepsi 0A): otomatis memberi eksepsi kepada master Modbus/TCP dan UDP, dan diam kepada master serial</translation>
    </message>
    <message>
        <location line="-22"/>
        <source>Units to other devices, separated by spaces, each UNITS[:DEVICE_UNIT]=URL: 1-10=rtu:///dev/ttyUSB0 or 1:17=tcp://10.0.0.5:502 (the master&apos;s unit 1 is the device&apos;s unit 17). The first route that serves a unit takes it; the target above takes the units no route serves. A route&apos;s URL may give its own timeout= and retries= (1:17=tcp://10.0.0.5:502?timeout=300ms&amp;retries=0).</source>
        <translation>Unit ke perangkat lain, dipisah spasi, masing-masing UNIT[:UNIT_PERANGKAT]=URL: 1-10=rtu:///dev/ttyUSB0 atau 1:17=tcp://10.0.0.5:502 (unit 1 milik master adalah unit 17 milik perangkat). Rute pertama yang melayani sebuah unit mengambilnya; target di atas mengambil unit yang tidak dilayani rute mana pun. URL sebuah rute dapat memberi timeout= dan retries= sendiri (1:17=tcp://10.0.0.5:502?timeout=300ms&amp;retries=0).</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Further attempts of a read after a timeout or a damaged answer, before the master gets its 0B or silence (a write is sent once), unless a route&apos;s URL gives retries=</source>
        <translation>Percobaan tambahan untuk pembacaan setelah habis waktu atau jawaban rusak, sebelum master menerima 0B atau diam (penulisan dikirim sekali), kecuali URL rute memberi retries=</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>none</source>
        <translation>tidak ada</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A fault rules file (the simulator&apos;s rules: drop, delay, exception, wrong checksum, wrong unit, close...; docs/profiles.md &quot;Faults&quot;) applied to the devices&apos; answers on their way back, so a master&apos;s handling of a misbehaving device can be tried without touching either. Read when the tap starts; empty: every answer passes unchanged</source>
        <translation>Berkas aturan gangguan (aturan simulator: drop, delay, exception, checksum salah, unit salah, close...; docs/profiles.md &quot;Faults&quot;) yang diterapkan pada jawaban perangkat saat kembali, sehingga cara master menangani perangkat yang bermasalah dapat dicoba tanpa menyentuh keduanya. Dibaca saat tap dimulai; kosong: setiap jawaban diteruskan tanpa perubahan</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Masters connect to:</source>
        <translation>Master tersambung ke:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Routes:</source>
        <translation>Rute:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>No answer:</source>
        <translation>Tanpa jawaban:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Retries:</source>
        <translation>Ulangan:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Faults:</source>
        <translation>Gangguan:</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Masters connect to: type where the masters connect, e.g. tcp://127.0.0.1:5020 (port 0: any free port).</source>
        <translation>Master tersambung ke: ketik tempat master tersambung, mis. tcp://127.0.0.1:5020 (port 0: port bebas mana pun).</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Masters connect to: &apos;%1&apos;: %2</source>
        <translation>Master tersambung ke: &apos;%1&apos;: %2</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Routes: %1</source>
        <translation>Rute: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The tap forwards Modbus: a target with framing=delimited has no unit ids to route.</source>
        <translation>Sadapan meneruskan Modbus: target dengan framing=delimited tidak punya id unit untuk dirutekan.</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Faults: %1</source>
        <translation>Gangguan: %1</translation>
    </message>
    <message>
        <location line="+100"/>
        <source>Tap: %1 requests from masters, %2 forwarded: %3 answered, %4 exceptions from devices, %5 without answer, %6 link errors, %7 damaged; %8 without route, %9 writes refused; %10 waiting</source>
        <translation>Sadap: %1 permintaan dari master, %2 diteruskan: %3 dijawab, %4 eksepsi dari perangkat, %5 tanpa jawaban, %6 galat tautan, %7 rusak; %8 tanpa rute, %9 penulisan ditolak; %10 menunggu</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>; devices answered in %1 on average</source>
        <translation>; perangkat menjawab dalam rata-rata %1</translation>
    </message>
</context>
<context>
    <name>mbscope::TapMode</name>
    <message>
        <location filename="../../ui/shell/tapmode.cpp" line="+22"/>
        <source>The tap could not start: %1. Choose another port in Masters connect to (port 0: any free port), or stop the program that listens there.</source>
        <translation>Sadapan tidak dapat dimulai: %1. Pilih port lain di Master tersambung ke (port 0: port bebas mana pun), atau hentikan program yang mendengarkan di sana.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The tap did not start</source>
        <translation>Sadapan tidak dimulai</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The tap&apos;s target failed: %1. The masters get exception 0B (or silence) until it answers again; their next request opens the link again. Press Disconnect to stop the tap.</source>
        <translation>Target sadapan gagal: %1. Master menerima eksepsi 0B (atau diam) sampai target menjawab lagi; permintaan berikutnya membuka tautan lagi. Tekan Putuskan untuk menghentikan sadapan.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Tap started, the same as: mbscope tap %1</source>
        <translation>Sadapan dimulai, sama dengan: mbscope tap %1</translation>
    </message>
</context>
<context>
    <name>mbscope::TapRunner</name>
    <message>
        <location filename="../../ui/link/taprunner.cpp" line="+68"/>
        <source>%1: cannot listen</source>
        <translation>%1: tidak dapat mendengarkan</translation>
    </message>
</context>
<context>
    <name>mbscope::Theme</name>
    <message>
        <location filename="../../ui/common/theme.cpp" line="+114"/>
        <source>Light</source>
        <translation>Terang</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Dark</source>
        <translation>Gelap</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Follow the desktop</source>
        <translation>Ikuti desktop</translation>
    </message>
</context>
<context>
    <name>mbscope::TimingResultTree</name>
    <message>
        <location filename="../../ui/discovery/timingresulttree.cpp" line="+13"/>
        <location line="+55"/>
        <location line="+15"/>
        <location line="+30"/>
        <location line="+1"/>
        <location line="+1"/>
        <source>%1 ms</source>
        <translation>%1 md</translation>
    </message>
    <message>
        <location line="-84"/>
        <source>Measurement</source>
        <translation>Pengukuran</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Result</source>
        <translation>Hasil</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>First answer after connecting</source>
        <translation>Jawaban pertama setelah tersambung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>none within %1 ms</source>
        <translation>tidak ada dalam %1 md</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 ms (%2 failed before it)</source>
        <translation>%1 md (%2 gagal sebelumnya)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Warm-up after connecting</source>
        <translation>Pemanasan setelah tersambung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 ms (answered after waiting %1 ms, not after %2 ms)</source>
        <translation>%1 ms (dijawab setelah menunggu %1 ms, tidak setelah %2 ms)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Gaps between requests</source>
        <translation>Jeda antarpermintaan</translation>
    </message>
    <message numerus="yes">
        <location line="+0"/>
        <source>%n tried, longest first</source>
        <translation>
            <numerusform>%n dicoba, terpanjang lebih dulu</numerusform>
        </translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 ok, %2 failed, slowest %3</source>
        <translation>%1 ok, %2 gagal, paling lambat %3</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>shorter</source>
        <translation>lebih pendek</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>not measured: the device hangs up after each answer and each new connection waits its warm-up (%1 ms)</source>
        <translation>tidak diukur: perangkat memutus sambungan setelah setiap jawaban dan setiap sambungan baru menunggu pemanasannya (%1 ms)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Shortest gap without errors</source>
        <translation>Jeda terpendek tanpa galat</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not measured (the warm-up kept every request apart)</source>
        <translation>tidak diukur (pemanasan menjaga jarak setiap permintaan)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not measured (stopped before a gap was tried through)</source>
        <translation>tidak diukur (dihentikan sebelum sebuah jeda dicoba sampai selesai)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>none of those tried (every gap had errors)</source>
        <translation>tidak satu pun yang dicoba (setiap jeda ada galat)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 ms (shorter gaps not tried: stopped)</source>
        <translation>%1 ms (jeda yang lebih pendek tidak dicoba: dihentikan)</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+8"/>
        <source>Largest read answered</source>
        <translation>Baca terbesar yang dijawab</translation>
    </message>
    <message>
        <location line="-7"/>
        <source>%1 at address %2 (an answer PDU of %3 bytes)</source>
        <translation>%1 di alamat %2 (PDU jawaban %3 bita)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>at least %1 at address %2 (an answer PDU of %3 bytes; stopped before the largest was found)</source>
        <translation>setidaknya %1 di alamat %2 (PDU jawaban %3 byte; dihentikan sebelum yang terbesar ditemukan)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>: one more ran past the device&apos;s map (no exception 03), not a quantity limit</source>
        <translation>: satu lagi melewati peta perangkat (tanpa pengecualian 03), bukan batas jumlah</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>not measured</source>
        <translation>tidak diukur</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Connection after each answer</source>
        <translation>Koneksi setelah tiap jawaban</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>closed by the device (%1 connections for %2 answers): pipelining and clients at once not measured</source>
        <translation>ditutup oleh perangkat (%1 koneksi untuk %2 jawaban): pipelining dan klien sekaligus tidak diukur</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>kept open</source>
        <translation>tetap terbuka</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Pipelined requests</source>
        <translation>Permintaan pipelined</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 of %2 answered: pipelining works</source>
        <translation>%1 dari %2 dijawab: pipelining berfungsi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 of %2 answered: send one at a time</source>
        <translation>%1 dari %2 dijawab: kirim satu per satu</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>TCP clients served at once</source>
        <translation>Klien TCP dilayani sekaligus</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (client %2 was served by closing client 1: the device knocks its oldest client off)</source>
        <translation>%1 (klien %2 dilayani dengan menutup klien 1: perangkat menendang klien tertuanya)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 (all tried; there may be room for more)</source>
        <translation>%1 (semua yang dicoba; mungkin masih muat lebih banyak)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (client %2 was not served)</source>
        <translation>%1 (klien %2 tidak dilayani)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Recommended</source>
        <translation>Disarankan</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>twice the shortest clean gap, three times the slowest answer</source>
        <translation>dua kali jeda bersih terpendek, tiga kali jawaban paling lambat</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gap between requests</source>
        <translation>Jeda antarpermintaan</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>none: no gap was measured</source>
        <translation>tidak ada: tidak ada jeda yang diukur</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Timeout</source>
        <translation>Batas waktu</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pause after connecting</source>
        <translation>Jeda setelah tersambung</translation>
    </message>
</context>
<context>
    <name>mbscope::TimingScanDialog</name>
    <message>
        <location filename="../../ui/discovery/timingscandialog.cpp" line="+37"/>
        <source> ms</source>
        <translation> md</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Start</source>
        <translation>&amp;Mulai</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sto&amp;p</source>
        <translation>&amp;Hentikan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Copy settings</source>
        <translation>&amp;Salin pengaturan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Record &amp;limits in profile…</source>
        <translation>Catat &amp;batas di profil…</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Time a unit</source>
        <translation>Ukur waktu sebuah unit</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The link of the unit. The scan opens connections of its own.</source>
        <translation>Link unit tersebut. Pemindaian membuka sambungannya sendiri.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The read asked throughout: a timing scan never writes.</source>
        <translation>Baca yang ditanyakan sepanjang pemindaian: pengukuran waktu tidak pernah menulis.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Quiet times between requests to try, in milliseconds, from the longest down; the scan stops going shorter once errors start.</source>
        <translation>Waktu hening antarpermintaan yang dicoba, dalam milidetik, dari yang terpanjang; pemindaian berhenti memendekkan begitu galat mulai muncul.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Requests asked at each gap.</source>
        <translation>Permintaan yang ditanyakan pada setiap jeda.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Modbus TCP: requests sent without waiting for answers.</source>
        <translation>Modbus TCP: permintaan dikirim tanpa menunggu jawaban.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>TCP links: connections held open at once, each asked in turn.</source>
        <translation>Link TCP: sambungan yang dibuka sekaligus, masing-masing ditanya bergiliran.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>address</source>
        <translation>alamat</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>ms, asked</source>
        <translation>md, ditanya</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>times each</source>
        <translation>kali masing-masing</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>pipelined, up to</source>
        <translation>pipelined, hingga</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>clients at once</source>
        <translation>klien sekaligus</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&amp;Target:</source>
        <translation>Tu&amp;juan:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Unit:</source>
        <translation>&amp;Unit:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Gaps:</source>
        <translation>Je&amp;da:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>TCP &amp;requests:</source>
        <translation>&amp;Permintaan TCP:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>T&amp;imeout:</source>
        <translation>Batas &amp;waktu:</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>The recommended settings as text: a watch link&apos;s gapMs and timeoutMs, mbscope&apos;s --timeout and Telegraf&apos;s modbus input.</source>
        <translation>Pengaturan yang disarankan sebagai teks: gapMs dan timeoutMs link pantauan, --timeout mbscope, dan input modbus Telegraf.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Merge what was measured (minGapMs, warmUpMs, maxClients, maxQuantity) into an existing device profile&apos;s limits, such as the map scan&apos;s draft; its other contents stay.</source>
        <translation>Gabungkan hasil pengukuran (minGapMs, warmUpMs, maxClients, maxQuantity) ke batas profil perangkat yang sudah ada, seperti draf pemindaian peta; isi lainnya tetap.</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Measuring %1: %2 of %3 steps</source>
        <translation>Mengukur %1: %2 dari %3 langkah</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Asks the read again and again, at shorter and shorter gaps, and says what the unit stood. Never writes.</source>
        <translation>Menanyakan baca itu berulang-ulang, dengan jeda makin pendek, dan mengatakan apa yang sanggup dilayani unit. Tidak pernah menulis.</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Give the link of the unit, e.g. tcp://192.168.1.10:502.</source>
        <translation>Berikan link unit tersebut, mis. tcp://192.168.1.10:502.</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Gaps: &quot;%1&quot; is not a number of milliseconds from 0 to 60000.</source>
        <translation>Jeda: &quot;%1&quot; bukan bilangan milidetik dari 0 sampai 60000.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Gaps: give at least one, e.g. 100, 20, 0.</source>
        <translation>Jeda: berikan paling sedikit satu, mis. 100, 20, 0.</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>Stopped before the first answer: nothing was measured.</source>
        <translation>Dihentikan sebelum jawaban pertama: tidak ada yang diukur.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The time limit of %1 came before the first answer: nothing was measured.</source>
        <translation>Batas waktu %1 tercapai sebelum jawaban pertama: tidak ada yang diukur.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>No good answer from unit %1 on %2: nothing to time.</source>
        <translation>Tidak ada jawaban baik dari unit %1 di %2: tidak ada yang bisa diukur.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stopped: the measurements after it were not made.</source>
        <translation>Dihentikan: pengukuran sesudahnya tidak dilakukan.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Time limit of %1 reached: the measurements after it were not made.</source>
        <translation>Batas waktu %1 tercapai: pengukuran sesudahnya tidak dilakukan.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Done: a gap of %1 ms and a timeout of %2 ms are recommended.</source>
        <translation>Selesai: disarankan jeda %1 md dan batas waktu %2 md.</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>The recommended settings are on the clipboard.</source>
        <translation>Pengaturan yang disarankan ada di papan klip.</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Record limits in profile</source>
        <translation>Catat batas di profil</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Device profiles (*.json)</source>
        <translation>Profil perangkat (*.json)</translation>
    </message>
</context>
<context>
    <name>mbscope::TlsFilesField</name>
    <message>
        <location filename="../../ui/link/tlsfilesfield.cpp" line="+19"/>
        <source>C&amp;ertificate:</source>
        <translation>S&amp;ertifikat:</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>client certificate (PEM)</source>
        <translation>sertifikat klien (PEM)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Choose this client&apos;s certificate (PEM)</source>
        <translation>Pilih sertifikat klien ini (PEM)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Key:</source>
        <translation>&amp;Kunci:</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>its private key (PEM)</source>
        <translation>kunci privatnya (PEM)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Choose the private key of the client certificate (PEM, no passphrase)</source>
        <translation>Pilih kunci privat sertifikat klien (PEM, tanpa passphrase)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>C&amp;A:</source>
        <translation>C&amp;A:</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>device&apos;s CA (PEM; empty: system CAs)</source>
        <translation>CA perangkat (PEM; kosong: CA sistem)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Choose the CA certificate that signed the device&apos;s certificate (PEM)</source>
        <translation>Pilih sertifikat CA yang menandatangani sertifikat perangkat (PEM)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>MODBUS/TCP Security (port 802) is mutual TLS: the device asks for this client&apos;s certificate and key, and its own certificate is checked against the CA file (or the system&apos;s CAs).</source>
        <translation>MODBUS/TCP Security (port 802) adalah TLS dua arah: perangkat meminta sertifikat dan kunci klien ini, dan sertifikat perangkat sendiri diperiksa terhadap berkas CA (atau CA sistem).</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>PEM files (*.pem *.crt *.cer *.key);;All files (*)</source>
        <translation>Berkas PEM (*.pem *.crt *.cer *.key);;Semua berkas (*)</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>The %1 file &apos;%2&apos; does not exist: choose it with the … button beside the field.</source>
        <translation>Berkas %1 &apos;%2&apos; tidak ada: pilih dengan tombol … di samping kolomnya.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The %1 file &apos;%2&apos; is a folder: choose the PEM file inside it.</source>
        <translation>Berkas %1 &apos;%2&apos; adalah folder: pilih berkas PEM di dalamnya.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The %1 file &apos;%2&apos; cannot be read (permission denied): make it readable by your user.</source>
        <translation>Berkas %1 &apos;%2&apos; tidak dapat dibaca (izin ditolak): buat agar dapat dibaca oleh user Anda.</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>A private key was given without its certificate: choose the client certificate too (mutual TLS needs both).</source>
        <translation>Kunci privat diberikan tanpa sertifikatnya: pilih juga sertifikat klien (TLS dua arah memerlukan keduanya).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A certificate was given without its private key: choose the key file too (mutual TLS needs both).</source>
        <translation>Sertifikat diberikan tanpa kunci privatnya: pilih juga berkas kuncinya (TLS dua arah memerlukan keduanya).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>certificate</source>
        <translation>sertifikat</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>private key</source>
        <translation>kunci privat</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CA certificate</source>
        <translation>sertifikat CA</translation>
    </message>
</context>
<context>
    <name>mbscope::ToolsMenu</name>
    <message>
        <location filename="../../ui/shell/toolsmenu.cpp" line="+35"/>
        <source>&amp;Tools</source>
        <translation>&amp;Alat</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Scan for units…</source>
        <translation>Pi&amp;ndai unit…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Ask every unit id of a link the same read and list what each did</source>
        <translation>Tanyai setiap id unit pada satu link dengan pembacaan yang sama dan tampilkan apa yang dilakukan masing-masing</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Conformance…</source>
        <translation>&amp;Kesesuaian…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Run the conformance battery of mbscope conform against a slave: a verdict per check with its clause</source>
        <translation>Jalankan rangkaian uji kesesuaian mbscope conform terhadap sebuah slave: satu hasil per pemeriksaan beserta pasalnya</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Export map…</source>
        <translation>&amp;Ekspor peta…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Write a device profile&apos;s register map for Node-RED, Telegraf, Home Assistant, modbus_exporter or CSV, verified against the device first if you like (mbscope export-map)</source>
        <translation>Tulis peta register profil perangkat untuk Node-RED, Telegraf, Home Assistant, modbus_exporter atau CSV, diverifikasi terhadap perangkat lebih dulu bila mau (mbscope export-map)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Preferences…</source>
        <translation>&amp;Preferensi…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Help</source>
        <translation>Ba&amp;ntuan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;About mbscope</source>
        <translation>&amp;Tentang mbscope</translation>
    </message>
    <message>
        <location line="+82"/>
        <source>Recording settings apply from the next connection.</source>
        <translation>Pengaturan perekaman berlaku mulai sambungan berikutnya.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The new language is used when mbscope is started again.</source>
        <translation>Bahasa yang baru dipakai saat mbscope dijalankan lagi.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>About mbscope</source>
        <translation>Tentang mbscope</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&lt;h3&gt;mbscope %1&lt;/h3&gt;&lt;p&gt;A bench for testing and analysing Modbus devices: send exactly the bytes you mean, see every field of the answer explained, measure how the device behaves.&lt;/p&gt;&lt;p&gt;Licensed under the GNU General Public License, version 3 or (at your option) any later version (GPL-3.0-or-later). This program comes with ABSOLUTELY NO WARRANTY.&lt;/p&gt;&lt;p&gt;Built with Qt %2 and QCustomPlot.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;mbscope %1&lt;/h3&gt;&lt;p&gt;Meja uji untuk menguji dan menganalisis perangkat Modbus: kirim persis byte yang Anda maksud, lihat setiap field jawaban dijelaskan, ukur bagaimana perangkat berperilaku.&lt;/p&gt;&lt;p&gt;Dilisensikan di bawah GNU General Public License, versi 3 atau (sesuai pilihan Anda) versi yang lebih baru (GPL-3.0-or-later). Program ini datang TANPA JAMINAN APA PUN.&lt;/p&gt;&lt;p&gt;Dibuat dengan Qt %2 dan QCustomPlot.&lt;/p&gt;</translation>
    </message>
</context>
<context>
    <name>mbscope::TrafficModel</name>
    <message>
        <location filename="../../ui/traffic/trafficmodeldata.cpp" line="+21"/>
        <source>No.</source>
        <translation>No.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Time (s)</source>
        <translation>Waktu (s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Dir</source>
        <translation>Arah</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Link</source>
        <translation>Link</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Unit</source>
        <translation>Unit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Function</source>
        <translation>Fungsi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Length</source>
        <translation>Panjang</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Latency</source>
        <translation>Latensi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Verdict</source>
        <translation>Hasil</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bytes</source>
        <translation>Byte</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Seconds since the first frame listed (monotonic clock)</source>
        <translation>Detik sejak frame pertama di daftar (jam monotonik)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>From the request&apos;s write to the first byte of its answer, as the recording keeps them; the Analysis dock measures from the request&apos;s last byte to the answer&apos;s last byte</source>
        <translation>Dari penulisan permintaan sampai byte pertama jawabannya, seperti yang disimpan rekaman; dok Analisis mengukur dari byte terakhir permintaan sampai byte terakhir jawaban</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>What became of the frame: a request is &apos;sent&apos;, its answer carries the verdict</source>
        <translation>Apa yang terjadi pada frame: permintaan berstatus &apos;terkirim&apos;, jawabannya membawa hasilnya</translation>
    </message>
    <message>
        <location line="+67"/>
        <source>link %1</source>
        <translation>link %1</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1 Exception to %2</source>
        <translation>%1 Pengecualian untuk %2</translation>
    </message>
    <message>
        <location line="+50"/>
        <source>No bytes</source>
        <translation>Tanpa byte</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Not an answer to any request sent</source>
        <translation>Bukan jawaban atas permintaan yang dikirim</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Answers frame %1</source>
        <translation>Menjawab frame %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Answered in frame %1</source>
        <translation>Dijawab di frame %1</translation>
    </message>
</context>
<context>
    <name>mbscope::TrafficMonitor</name>
    <message>
        <location filename="../../ui/traffic/trafficmonitor.cpp" line="+75"/>
        <location line="+5"/>
        <location line="+15"/>
        <source>any</source>
        <translation>semua</translation>
    </message>
    <message>
        <location line="-19"/>
        <source>Show only frames of this unit id</source>
        <translation>Tampilkan hanya frame dengan ID unit ini</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Show only frames of this function code (its exception responses included)</source>
        <translation>Tampilkan hanya frame dengan kode fungsi ini (termasuk respons pengecualiannya)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>both</source>
        <translation>keduanya</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>problems only</source>
        <translation>hanya masalah</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+220"/>
        <source>Pause</source>
        <translation>Jeda</translation>
    </message>
    <message>
        <location line="-218"/>
        <source>Hold new frames back from the list; nothing is dropped, they appear on resume</source>
        <translation>Tahan frame baru dari daftar; tidak ada yang dibuang, frame muncul saat dilanjutkan</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Clear</source>
        <translation>Kosongkan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Empty the list (the connection&apos;s traffic journal keeps every frame, unless recording is turned off in Preferences)</source>
        <translation>Kosongkan daftar (jurnal lalu lintas sambungan menyimpan setiap frame, kecuali perekaman dimatikan di Preferensi)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Save &amp;Traffic As…</source>
        <translation>Simpan &amp;Lalu Lintas Sebagai…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save the frames listed (all, or what the filter shows) as a traffic journal, a Wireshark capture (pcapng, pcap), CSV or JSON lines</source>
        <translation>Simpan frame yang terdaftar (semua, atau yang ditampilkan filter) sebagai jurnal lalu lintas, tangkapan Wireshark (pcapng, pcap), CSV atau baris JSON</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Save…</source>
        <translation>Simpan…</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Find: hex bytes or text (Enter, F3)</source>
        <translation>Cari: byte hex atau teks (Enter, F3)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Find previous (Shift+F3)</source>
        <translation>Cari sebelumnya (Shift+F3)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Find next (F3)</source>
        <translation>Cari berikutnya (F3)</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Unit:</source>
        <translation>Unit:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Function:</source>
        <translation>Fungsi:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Direction:</source>
        <translation>Arah:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Verdict:</source>
        <translation>Hasil:</translation>
    </message>
    <message>
        <location line="+67"/>
        <source>nothing to save: the list is empty</source>
        <translation>tidak ada yang disimpan: daftar kosong</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+46"/>
        <source>Save Traffic</source>
        <translation>Simpan Lalu Lintas</translation>
    </message>
    <message>
        <location line="-45"/>
        <source>The filter shows %1 of the %2 frames listed. Save which?</source>
        <translation>Filter menampilkan %1 dari %2 frame yang terdaftar. Simpan yang mana?</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;All frames</source>
        <translation>&amp;Semua frame</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Shown frames</source>
        <translation>Frame yang &amp;ditampilkan</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Save Traffic As</source>
        <translation>Simpan Lalu Lintas Sebagai</translation>
    </message>
    <message>
        <location line="+87"/>
        <source>Resume</source>
        <translation>Lanjutkan</translation>
    </message>
    <message>
        <location line="+98"/>
        <source>No frame shown matches “%1”</source>
        <translation>Tidak ada frame yang cocok dengan “%1”</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1 frames</source>
        <translation>%1 frame</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>, %1 shown</source>
        <translation>, %1 ditampilkan</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> · paused: %1 new frames held</source>
        <translation> · dijeda: %1 frame baru ditahan</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> · %1 oldest dropped from the list</source>
        <translation> · %1 terlama dibuang dari daftar</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> · older frames are no longer kept on disk: %1</source>
        <translation> · frame lama tidak lagi disimpan di disk: %1</translation>
    </message>
</context>
<context>
    <name>mbscope::TrafficStyle</name>
    <message>
        <location filename="../../ui/common/trafficstyle.cpp" line="+37"/>
        <source>ok</source>
        <translation>ok</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>exception</source>
        <translation>pengecualian</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>timeout</source>
        <translation>waktu habis</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>crc error</source>
        <translation>error CRC</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>malformed</source>
        <translation>cacat</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unexpected</source>
        <translation>tak terduga</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>link error</source>
        <translation>error link</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>broadcast</source>
        <translation>broadcast</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>late</source>
        <translation>terlambat</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sent</source>
        <translation>terkirim</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unsolicited</source>
        <translation>tak diminta</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>garbage</source>
        <translation>sampah</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>out</source>
        <translation>keluar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>in</source>
        <translation>masuk</translation>
    </message>
</context>
<context>
    <name>mbscope::TransactionView</name>
    <message>
        <location filename="../../ui/decode/transactionview.cpp" line="+18"/>
        <source>Back to live</source>
        <translation>Kembali ke langsung</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Show the link&apos;s answers as they come again</source>
        <translation>Tampilkan lagi jawaban link saat datang</translation>
    </message>
    <message>
        <location line="+54"/>
        <source>Showing transaction %1, picked in the traffic list: the link&apos;s new answers are not shown.</source>
        <translation>Menampilkan transaksi %1, dipilih di daftar lalu lintas: jawaban baru link tidak ditampilkan.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Showing a frame picked in the traffic list: the link&apos;s new answers are not shown.</source>
        <translation>Menampilkan frame yang dipilih di daftar lalu lintas: jawaban baru link tidak ditampilkan.</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>mbscope::TrendPanels</name>
    <message>
        <location filename="../../ui/analysis/trendpanels.cpp" line="+21"/>
        <source>Latency over time</source>
        <translation>Latensi terhadap waktu</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Register trends</source>
        <translation>Tren register</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sweep</source>
        <translation>Sapuan</translation>
    </message>
</context>
<context>
    <name>mbscope::TrendSeries</name>
    <message>
        <location filename="../../ui/analysis/trendseries.cpp" line="+35"/>
        <source>address %1</source>
        <translation>alamat %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 › %2</source>
        <translation>%1 › %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 › %2 (%3)</source>
        <translation>%1 › %2 (%3)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>bit</source>
        <translation>bit</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1, %2</source>
        <translation>%1, %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1, %2 (%3)</source>
        <translation>%1, %2 (%3)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: watch %2, address %3, as the watch decodes it</source>
        <translation>%1: pantauan %2, alamat %3, sebagaimana pantauan mendekodenya</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1, PDU address %2</source>
        <translation>%1, alamat PDU %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1, %2, value = raw × %3 + %4</source>
        <translation>%1, %2, nilai = mentah × %3 + %4</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 (profile %2)</source>
        <translation>%1 (profil %2)</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>%1 [%2]</source>
        <translation>%1 [%2]</translation>
    </message>
</context>
<context>
    <name>mbscope::WatchDialog</name>
    <message>
        <location filename="../../ui/watch/watchdialog.cpp" line="+51"/>
        <source>Each address holds a 32-bit value (&amp;Enron/Daniel)</source>
        <translation>Tiap alamat berisi nilai 32-bit (&amp;Enron/Daniel)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Poll this watch (&amp;on)</source>
        <translation>Polling pantauan ini (&amp;aktif)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Watch</source>
        <translation>Pantauan</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The link URL: tcp://host:port, rtu-tcp://host:port, udp://host:port, rtu:///dev/ttyUSB0?baud=19200</source>
        <translation>URL link: tcp://host:port, rtu-tcp://host:port, udp://host:port, rtu:///dev/ttyUSB0?baud=19200</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>01 Read coils</source>
        <translation>01 Baca coil</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>02 Read discrete inputs</source>
        <translation>02 Baca input diskret</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>03 Read holding registers</source>
        <translation>03 Baca holding register</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>04 Read input registers</source>
        <translation>04 Baca input register</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>18 Read FIFO queue</source>
        <translation>18 Baca antrean FIFO</translation>
    </message>
    <message>
        <location line="+5"/>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Start to start; 0: as fast as the link allows</source>
        <translation>Dari awal ke awal; 0: secepat yang dimungkinkan link</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Name:</source>
        <translation>&amp;Nama:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Tar&amp;get:</source>
        <translation>Tar&amp;get:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Unit:</source>
        <translation>&amp;Unit:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Function:</source>
        <translation>&amp;Fungsi:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Address:</source>
        <translation>A&amp;lamat:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Quantity:</source>
        <translation>&amp;Jumlah:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Interval:</source>
        <translation>&amp;Interval:</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Add &amp;point</source>
        <translation>Tambah &amp;titik</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remo&amp;ve point</source>
        <translation>&amp;Hapus titik</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Add &amp;rule</source>
        <translation>Tam&amp;bah aturan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remove ru&amp;le</source>
        <translation>Hapu&amp;s aturan</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Poin&amp;ts</source>
        <translation>Titi&amp;k</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rule&amp;s</source>
        <translation>Atu&amp;ran</translation>
    </message>
    <message>
        <location line="+52"/>
        <source>Name: give the watch a name (used in CSV file names and logs)</source>
        <translation>Nama: beri pantauan sebuah nama (dipakai di nama file CSV dan log)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Name: another watch is called &apos;%1&apos;</source>
        <translation>Nama: pantauan lain sudah bernama &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Target: %1</source>
        <translation>Target: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Address: %1</source>
        <translation>Alamat: %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Point at address %1 lies outside the watch&apos;s addresses %2 to %3</source>
        <translation>Titik di alamat %1 berada di luar alamat pantauan %2 sampai %3</translation>
    </message>
</context>
<context>
    <name>mbscope::WatchFactory</name>
    <message>
        <location filename="../../ui/watch/watchfactory.cpp" line="+100"/>
        <source>The composer holds no request: build a read (01-04) first.</source>
        <translation>Penyusun tidak berisi permintaan: buat dulu pembacaan (01-04).</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The composer&apos;s request cannot be read: %1</source>
        <translation>Permintaan penyusun tidak dapat dibaca: %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The composer&apos;s request is function 0x%1: a watch reads (01-04, or the FIFO 18).</source>
        <translation>Permintaan penyusun adalah fungsi 0x%1: pantauan membaca (01-04, atau FIFO 18).</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The composer&apos;s request is %1 bytes long: a read needs its address and quantity.</source>
        <translation>Permintaan penyusun panjangnya %1 byte: pembacaan perlu alamat dan jumlahnya.</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>The composer&apos;s request reads %1 values: a watch reads 1 to %2.</source>
        <translation>Permintaan penyusun membaca %1 nilai: pantauan membaca 1 sampai %2.</translation>
    </message>
</context>
<context>
    <name>mbscope::WatchLogControl</name>
    <message>
        <location filename="../../ui/watch/watchlogcontrol.cpp" line="+19"/>
        <source>&amp;Log values to CSV</source>
        <translation>&amp;Catat nilai ke CSV</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CSV log settin&amp;gs…</source>
        <translation>Pengaturan log CS&amp;V…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Log to CSV</source>
        <translation>Catat ke CSV</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Write the watches&apos; values to CSV files while they run (one file per watch)</source>
        <translation>Tulis nilai pantauan ke file CSV selama berjalan (satu file per pantauan)</translation>
    </message>
    <message numerus="yes">
        <location line="+109"/>
        <source>(%n row(s) could not be written)</source>
        <translation>
            <numerusform>(%n baris tidak dapat ditulis)</numerusform>
        </translation>
    </message>
    <message>
        <location line="-15"/>
        <source>Logging the watches to CSV in %1</source>
        <translation>Mencatat pantauan ke CSV di %1</translation>
    </message>
    <message numerus="yes">
        <location line="+13"/>
        <source>CSV log closed: %n file(s) in %1</source>
        <translation>
            <numerusform>Log CSV ditutup: %n file di %1</numerusform>
        </translation>
    </message>
    <message>
        <location line="-10"/>
        <source>The CSV log cannot be written: %1</source>
        <translation>Log CSV tidak dapat ditulis: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The CSV log cannot keep up with the polls: rows are dropped until it catches up</source>
        <translation>Log CSV tidak dapat mengikuti laju polling: baris dibuang sampai log menyusul</translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>The CSV log caught up: %n row(s) were dropped</source>
        <translation>
            <numerusform>Log CSV sudah menyusul: %n baris dibuang</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>mbscope::WatchLogDialog</name>
    <message>
        <location filename="../../ui/watch/watchlogdialog.cpp" line="+23"/>
        <source>&amp;Log while the watches run</source>
        <translation>&amp;Catat selama pantauan berjalan</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>CSV log of the watches</source>
        <translation>Log CSV pantauan</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>One CSV file per watch goes here; a folder that is not absolute is beside the session file</source>
        <translation>Satu file CSV per pantauan disimpan di sini; folder yang tidak absolut berada di samping file sesi</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Browse…</source>
        <translation>&amp;Telusuri…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>CSV log folder</source>
        <translation>Folder log CSV</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>A row per poll</source>
        <translation>Satu baris per polling</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A row when a value changed</source>
        <translation>Satu baris saat sebuah nilai berubah</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+3"/>
        <source>never</source>
        <translation>tidak pernah</translation>
    </message>
    <message>
        <location line="-2"/>
        <source> MiB</source>
        <translation> MiB</translation>
    </message>
    <message>
        <location line="+3"/>
        <source> min</source>
        <translation> mnt</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Folder:</source>
        <translation>&amp;Folder:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Rows:</source>
        <translation>&amp;Baris:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>New file after (&amp;size):</source>
        <translation>File baru setelah (&amp;ukuran):</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>New file after (&amp;age):</source>
        <translation>File baru setelah (u&amp;mur):</translation>
    </message>
</context>
<context>
    <name>mbscope::WatchPointTable</name>
    <message>
        <location filename="../../ui/watch/watchpointtable.cpp" line="+11"/>
        <source>Address</source>
        <translation>Alamat</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Name</source>
        <translation>Nama</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Format</source>
        <translation>Format</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Unit</source>
        <translation>Unit</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Scale</source>
        <translation>Skala</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Offset</source>
        <translation>Offset</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Writable</source>
        <translation>Dapat ditulis</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Address: the PDU address (0-based; 0x hex allowed). Format: u16, i16, u32-abcd, f32-cdab, ... Value = raw x scale + offset.</source>
        <translation>Alamat: alamat PDU (mulai 0; hex 0x boleh). Format: u16, i16, u32-abcd, f32-cdab, ... Nilai = mentah x skala + offset.</translation>
    </message>
    <message>
        <location line="+49"/>
        <source>point %1</source>
        <translation>titik %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1: address &apos;%2&apos; is not 0 to 65535</source>
        <translation>%1: alamat &apos;%2&apos; tidak di antara 0 dan 65535</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>%1: scale &apos;%2&apos; is not a number other than 0</source>
        <translation>%1: skala &apos;%2&apos; bukan angka selain 0</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1: offset &apos;%2&apos; is not a number</source>
        <translation>%1: offset &apos;%2&apos; bukan angka</translation>
    </message>
</context>
<context>
    <name>mbscope::WatchProfileDialog</name>
    <message>
        <location filename="../../ui/watch/watchprofiledialog.cpp" line="+28"/>
        <source>Watches from a device profile</source>
        <translation>Pantauan dari profil perangkat</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>A shipped profile&apos;s name, or the path of a profile file</source>
        <translation>Nama profil bawaan, atau path file profil</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Browse…</source>
        <translation>&amp;Telusuri…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Device profile</source>
        <translation>Profil perangkat</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Profiles (*.json)</source>
        <translation>Profil (*.json)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Profile:</source>
        <translation>&amp;Profil:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Unit:</source>
        <translation>&amp;Unit:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Target:</source>
        <translation>Tu&amp;juan:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Interval:</source>
        <translation>&amp;Interval:</translation>
    </message>
</context>
<context>
    <name>mbscope::WatchRuleTable</name>
    <message>
        <location filename="../../ui/watch/watchruletable.cpp" line="+29"/>
        <source>Point</source>
        <translation>Titik</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Condition</source>
        <translation>Kondisi</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+11"/>
        <source>Low</source>
        <translation>Bawah</translation>
    </message>
    <message>
        <location line="-11"/>
        <location line="+11"/>
        <source>High</source>
        <translation>Atas</translation>
    </message>
    <message>
        <location line="-11"/>
        <source>For polls</source>
        <translation>Selama polling</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Severity</source>
        <translation>Tingkat</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Colour</source>
        <translation>Warna</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Message</source>
        <translation>Pesan</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>above: value &gt; High; below: value &lt; Low; outside/inside: the range Low..High; equal/not equal: Low; bits: raw AND Low (a mask) not 0. A threshold the condition does not use is greyed out and empty. Colour: #RRGGBB, empty for the severity&apos;s.</source>
        <translation>di atas: nilai &gt; Atas; di bawah: nilai &lt; Bawah; di luar/di dalam: rentang Bawah..Atas; sama/tidak sama: Bawah; bit: mentah AND Bawah (sebuah mask) bukan 0. Ambang yang tidak dipakai kondisinya berwarna abu-abu dan kosong. Warna: #RRGGBB, kosong untuk warna tingkatnya.</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>above</source>
        <translation>di atas</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>below</source>
        <translation>di bawah</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>outside</source>
        <translation>di luar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>inside</source>
        <translation>di dalam</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>equal</source>
        <translation>sama dengan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not equal</source>
        <translation>tidak sama dengan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bits set</source>
        <translation>bit menyala</translation>
    </message>
    <message>
        <location line="+65"/>
        <source>&apos;%1&apos; does not use %2</source>
        <translation>&apos;%1&apos; tidak memakai %2</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>rule %1</source>
        <translation>aturan %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: name the point (its name or address)</source>
        <translation>%1: sebutkan titiknya (nama atau alamatnya)</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1: %2: &apos;%3&apos; does not use %2; clear it (it holds %4)</source>
        <translation>%1: %2: &apos;%3&apos; tidak memakai %2; kosongkan (isinya %4)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1: %2: &apos;%3&apos; needs a number here</source>
        <translation>%1: %2: &apos;%3&apos; memerlukan angka di sini</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: %2: &apos;%3&apos; is not a number</source>
        <translation>%1: %2: &apos;%3&apos; bukan angka</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>%1: Point: &apos;%2&apos; is neither a point&apos;s name nor an address of the watch</source>
        <translation>%1: Titik: &apos;%2&apos; bukan nama titik maupun alamat pada pantauan ini</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: %2: %3</source>
        <translation>%1: %2: %3</translation>
    </message>
    <message>
        <location line="-15"/>
        <source>%1: &apos;for polls&apos; must be 1 or more</source>
        <translation>%1: &apos;selama polling&apos; harus 1 atau lebih</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: colour &apos;%2&apos; is not #RRGGBB</source>
        <translation>%1: warna &apos;%2&apos; bukan #RRGGBB</translation>
    </message>
</context>
<context>
    <name>mbscope::WatchTableModel</name>
    <message>
        <location filename="../../ui/watch/watchtablemodel.cpp" line="+197"/>
        <source>Double-click or press F2 to write a new value</source>
        <translation>Klik ganda atau tekan F2 untuk menulis nilai baru</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Address</source>
        <translation>Alamat</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reference</source>
        <translation>Referensi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Name</source>
        <translation>Nama</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Value</source>
        <translation>Nilai</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Unit</source>
        <translation>Unit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rule</source>
        <translation>Aturan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Changed</source>
        <translation>Berubah</translation>
    </message>
</context>
<context>
    <name>mbscope::WatchValueWrite</name>
    <message>
        <location filename="../../ui/watch/watchvaluewrite.cpp" line="+23"/>
        <source>%1: only points marked writable of a coil (01) or holding register (03) watch are written</source>
        <translation>%1: hanya titik bertanda dapat ditulis dari pantauan coil (01) atau holding register (03) yang ditulis</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>address %1</source>
        <translation>alamat %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (address %2)</source>
        <translation>%1 (alamat %2)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: &apos;%2&apos; is not a coil value: expected 1 or 0 (on/off, true/false)</source>
        <translation>%1: &apos;%2&apos; bukan nilai coil: diharapkan 1 atau 0 (on/off, true/false)</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>%1: &apos;%2&apos; is not a number (the point is scaled: raw = (value - %3) / %4)</source>
        <translation>%1: &apos;%2&apos; bukan angka (titik ini berskala: mentah = (nilai - %3) / %4)</translation>
    </message>
</context>
<context>
    <name>mbscope::WatchWindow</name>
    <message>
        <location filename="../../ui/watch/watchwindow.cpp" line="+82"/>
        <source>polls %1 · ok %2 · exceptions %3 · timeouts %4</source>
        <translation>polling %1 · ok %2 · eksepsi %3 · timeout %4</translation>
    </message>
    <message>
        <location line="+3"/>
        <source> · other errors %1</source>
        <translation> · galat lain %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> · rules fired %1</source>
        <translation> · aturan terpicu %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> · latency %1 ms</source>
        <translation> · latensi %1 ms</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> · last error at %1: %2</source>
        <translation> · galat terakhir pukul %1: %2</translation>
    </message>
    <message>
        <location line="+72"/>
        <source>link: connecting</source>
        <translation>link: menyambung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>link: up</source>
        <translation>link: aktif</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>link: down (%1)</source>
        <translation>link: putus (%1)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>link: down (%1), retry in %2 s</source>
        <translation>link: putus (%1), coba lagi dalam %2 d</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>link: stopped</source>
        <translation>link: berhenti</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>, reconnected %1×</source>
        <translation>, tersambung ulang %1×</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Polling</source>
        <translation>Mem-polling</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Stopped</source>
        <translation>Dihentikan</translation>
    </message>
</context>
<context>
    <name>mbscope::WatchWorkspace</name>
    <message>
        <location filename="../../ui/watch/watchworkspace.cpp" line="+66"/>
        <source>No watches yet. A watch polls a block of a device at its own interval and shows its values with names, units and rule colours. Make one with Workspace → New watch (%1), from the composer&apos;s read request (%2) or from a device profile (%3); Start all (%4) polls them together.</source>
        <translation>Belum ada pantauan. Sebuah pantauan mem-polling satu blok perangkat pada intervalnya sendiri dan menampilkan nilainya dengan nama, unit, dan warna aturan. Buat dengan Daftar pantau → Pantauan baru (%1), dari permintaan baca penyusun (%2) atau dari profil perangkat (%3); Mulai semua (%4) mem-polling semuanya bersama.</translation>
    </message>
    <message>
        <location filename="../../ui/watch/watchworkspaceactions.cpp" line="+27"/>
        <source>&amp;New watch…</source>
        <translation>Pantauan &amp;baru…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>New watch</source>
        <translation>Pantauan baru</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>New watch from the composer&apos;s &amp;request</source>
        <translation>Pantauan baru dari &amp;permintaan penyusun</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>From request</source>
        <translation>Dari permintaan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>New watches from a device &amp;profile…</source>
        <translation>Pantauan baru dari p&amp;rofil perangkat…</translation>
    </message>
    <message numerus="yes">
        <location line="+7"/>
        <source>%n watch(es) made from %1</source>
        <translation>
            <numerusform>%n pantauan dibuat dari %1</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>From profile</source>
        <translation>Dari profil</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Edit watch…</source>
        <translation>&amp;Ubah pantauan…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Duplicate watch</source>
        <translation>&amp;Gandakan pantauan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Close watch</source>
        <translation>&amp;Tutup pantauan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Move watch le&amp;ft</source>
        <translation>Geser pantauan ke &amp;kiri</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Move watch r&amp;ight</source>
        <translation>Geser pantauan ke ka&amp;nan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Start all</source>
        <translation>&amp;Mulai semua</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>S&amp;top all</source>
        <translation>&amp;Hentikan semua</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Ne&amp;xt watch</source>
        <translation>Pantauan ber&amp;ikutnya</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&amp;Write value…</source>
        <translation>Tu&amp;lis nilai…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>C&amp;opy values</source>
        <translation>&amp;Salin nilai</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Poll t&amp;his watch</source>
        <translation>P&amp;olling pantauan ini</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Poll this watch</source>
        <translation>Polling pantauan ini</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Start or stop the current watch alone; the others go on as they are</source>
        <translation>Mulai atau hentikan pantauan ini saja; yang lain tetap seperti adanya</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Trend this &amp;value</source>
        <translation>Tren&amp;d nilai ini</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Plot the chosen value of this watch in Analysis → Register trends as it polls</source>
        <translation>Gambar nilai terpilih pantauan ini di Analisis → Tren register selama mem-polling</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>T&amp;abbed windows</source>
        <translation>Jendela b&amp;ertab</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Tabbed</source>
        <translation>Bertab</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Watches as tabs, or as windows tiled side by side</source>
        <translation>Pantauan sebagai tab, atau sebagai jendela berjajar</translation>
    </message>
    <message>
        <location filename="../../ui/watch/watchworkspace.cpp" line="+138"/>
        <source>%1 (off)</source>
        <translation>%1 (mati)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 (stopped)</source>
        <translation>%1 (dihentikan)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1, unit %2, every %3 ms</source>
        <translation>%1, unit %2, setiap %3 ms</translation>
    </message>
    <message>
        <location line="+133"/>
        <source>watch</source>
        <translation>pantauan</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>No composer to take a request from.</source>
        <translation>Tidak ada penyusun untuk diambil permintaannya.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Watch &apos;%1&apos; made from the composer&apos;s request</source>
        <translation>Pantauan &apos;%1&apos; dibuat dari permintaan penyusun</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The profile %1 was not loaded: %2</source>
        <translation>Profil %1 tidak dimuat: %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The profile %1 has no unit %2 with registers or bits to watch</source>
        <translation>Profil %1 tidak punya unit %2 dengan register atau bit untuk dipantau</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>No watches to start: make one first (Workspace → New watch)</source>
        <translation>Tidak ada pantauan untuk dimulai: buat dulu (Daftar pantau → Pantauan baru)</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>Written: %1</source>
        <translation>Ditulis: %1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Not written: %1</source>
        <translation>Tidak ditulis: %1</translation>
    </message>
    <message numerus="yes">
        <location line="-19"/>
        <source>Polling %n watch(es)</source>
        <translation>
            <numerusform>Mem-polling %n pantauan</numerusform>
        </translation>
    </message>
    <message>
        <location line="+36"/>
        <source>Watches stopped</source>
        <translation>Pantauan dihentikan</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>Polling watch &apos;%1&apos;</source>
        <translation>Mem-polling pantauan &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Watch &apos;%1&apos; stopped</source>
        <translation>Pantauan &apos;%1&apos; dihentikan</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Choose a value in a watch&apos;s table to trend</source>
        <translation>Pilih nilai di tabel pantauan untuk digambar trennya</translation>
    </message>
    <message>
        <location filename="../../ui/watch/watchworkspacewrites.cpp" line="+22"/>
        <source>Choose a value in a watch&apos;s table to write</source>
        <translation>Pilih nilai di tabel pantauan untuk ditulis</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Not writable: only points marked writable of a coil or holding register watch are written (Edit watch → Points → Writable)</source>
        <translation>Tidak dapat ditulis: hanya titik bertanda dapat ditulis dari pantauan coil atau holding register yang ditulis (Ubah pantauan → Titik → Dapat ditulis)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Write %1</source>
        <translation>Tulis %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>New value of %1 (%2):</source>
        <translation>Nilai baru %1 (%2):</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>No such value</source>
        <translation>Nilai itu tidak ada</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Not written: start the watches first (Start all, %1)</source>
        <translation>Tidak ditulis: mulai dulu pantauannya (Mulai semua, %1)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Writing %1 to %2</source>
        <translation>Menulis %1 ke %2</translation>
    </message>
</context>
</TS>
