<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="sr_Latn_RS">
<context>
    <name>QAbstractSpinBox</name>
    <message>
        <source>Step &amp;down</source>
        <translation>Korak na&amp;dole</translation>
    </message>
    <message>
        <source>&amp;Step up</source>
        <translation>Korak na&amp;gore</translation>
    </message>
    <message>
        <source>&amp;Select All</source>
        <translation>&amp;Izaberi sve</translation>
    </message>
</context>
<context>
    <name>QDockWidget</name>
    <message>
        <source>Close</source>
        <translation>Zatvori</translation>
    </message>
    <message>
        <source>Float</source>
        <translation>Odvoji</translation>
    </message>
    <message>
        <source>Undocks and re-attaches the dock widget</source>
        <translation>Odvaja panel i vraća ga na mesto</translation>
    </message>
    <message>
        <source>Closes the dock widget</source>
        <translation>Zatvara panel</translation>
    </message>
</context>
<context>
    <name>QFileDialog</name>
    <message>
        <source>Back</source>
        <translation>Nazad</translation>
    </message>
    <message>
        <source>File</source>
        <translation>Datoteka</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Otvori</translation>
    </message>
    <message>
        <source>&amp;Open</source>
        <translation>&amp;Otvori</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Sačuvaj</translation>
    </message>
    <message>
        <source>Alias</source>
        <translation>Alijas</translation>
    </message>
    <message>
        <source>Drive</source>
        <translation>Disk</translation>
    </message>
    <message>
        <source>Files</source>
        <translation>Datoteke</translation>
    </message>
    <message>
        <source>Show </source>
        <translation>Prikaži </translation>
    </message>
    <message>
        <source>&apos;%1&apos; is write protected.
Do you want to delete it anyway?</source>
        <translation>„%1“ je zaštićena od upisa.
Da li ipak želite da je obrišete?</translation>
    </message>
    <message>
        <source>Are you sure you want to delete &apos;%1&apos;?</source>
        <translation>Da li sigurno želite da obrišete „%1“?</translation>
    </message>
    <message>
        <source>List of places and bookmarks</source>
        <translation>Spisak mesta i obeleživača</translation>
    </message>
    <message>
        <source>File &amp;name:</source>
        <translation>&amp;Ime datoteke:</translation>
    </message>
    <message>
        <source>File Folder</source>
        <translation>Fascikla</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Obriši</translation>
    </message>
    <message>
        <source>New Folder</source>
        <translation>Nova fascikla</translation>
    </message>
    <message>
        <source>Folder</source>
        <translation>Fascikla</translation>
    </message>
    <message>
        <source>Parent Directory</source>
        <translation>Nadređena fascikla</translation>
    </message>
    <message>
        <source>&amp;New Folder</source>
        <translation>&amp;Nova fascikla</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Ukloni</translation>
    </message>
    <message>
        <source>My Computer</source>
        <translation>Moj računar</translation>
    </message>
    <message>
        <source>Look in:</source>
        <translation>Fascikla:</translation>
    </message>
    <message>
        <source>Create a New Folder</source>
        <translation>Napravi novu fasciklu</translation>
    </message>
    <message>
        <source>%1 File</source>
        <translation>%1 datoteka</translation>
    </message>
    <message>
        <source>Files of type:</source>
        <translation>Vrsta datoteka:</translation>
    </message>
    <message>
        <source>Find Directory</source>
        <translation>Izbor fascikle</translation>
    </message>
    <message>
        <source>Show &amp;hidden files</source>
        <translation>Prikaži &amp;skrivene datoteke</translation>
    </message>
    <message>
        <source>Save As</source>
        <translation>Sačuvaj kao</translation>
    </message>
    <message>
        <source>%1
Directory not found.
Please verify the correct directory name was given.</source>
        <translation>%1
Fascikla nije pronađena.
Proverite da li je ime fascikle tačno.</translation>
    </message>
    <message>
        <source>Sidebar</source>
        <translation>Bočna traka</translation>
    </message>
    <message>
        <source>List View</source>
        <translation>Spisak</translation>
    </message>
    <message>
        <source>&amp;Choose</source>
        <translation>&amp;Izaberi</translation>
    </message>
    <message>
        <source>&amp;Delete</source>
        <translation>&amp;Obriši</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Sve datoteke (*)</translation>
    </message>
    <message>
        <source>All Files (*)</source>
        <translation>Sve datoteke (*)</translation>
    </message>
    <message>
        <source>Directories</source>
        <translation>Fascikle</translation>
    </message>
    <message>
        <source>&amp;Rename</source>
        <translation>&amp;Preimenuj</translation>
    </message>
    <message>
        <source>Could not delete directory.</source>
        <translation>Fascikla nije mogla da se obriše.</translation>
    </message>
    <message>
        <source>Directory:</source>
        <translation>Fascikla:</translation>
    </message>
    <message>
        <source>Unknown</source>
        <translation>Nepoznato</translation>
    </message>
    <message>
        <source>%1 already exists.
Do you want to replace it?</source>
        <translation>%1 već postoji.
Da li želite da je zamenite?</translation>
    </message>
    <message>
        <source>Forward</source>
        <translation>Napred</translation>
    </message>
    <message>
        <source>Go forward</source>
        <translation>Idi napred</translation>
    </message>
    <message>
        <source>Go to the parent directory</source>
        <translation>Idi u nadređenu fasciklu</translation>
    </message>
    <message>
        <source>Recent Places</source>
        <translation>Nedavna mesta</translation>
    </message>
    <message>
        <source>Go back</source>
        <translation>Idi nazad</translation>
    </message>
    <message>
        <source>Change to detail view mode</source>
        <translation>Pređi na detaljan prikaz</translation>
    </message>
    <message>
        <source>Create New Folder</source>
        <translation>Napravi fasciklu</translation>
    </message>
    <message>
        <source>Shortcut</source>
        <translation>Prečica</translation>
    </message>
    <message>
        <source>Detail View</source>
        <translation>Detaljan prikaz</translation>
    </message>
    <message>
        <source>%1
File not found.
Please verify the correct file name was given.</source>
        <translation>%1
Datoteka nije pronađena.
Proverite da li je ime datoteke tačno.</translation>
    </message>
    <message>
        <source>Change to list view mode</source>
        <translation>Pređi na prikaz u obliku spiska</translation>
    </message>
</context>
<context>
    <name>QFileSystemModel</name>
    <message>
        <source>Kind</source>
        <translation>Vrsta</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Ime</translation>
    </message>
    <message>
        <source>Size</source>
        <translation>Veličina</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>Tip</translation>
    </message>
    <message>
        <source>My Computer</source>
        <translation>Moj računar</translation>
    </message>
    <message>
        <source>Computer</source>
        <translation>Računar</translation>
    </message>
    <message>
        <source>Invalid filename</source>
        <translation>Neispravno ime datoteke</translation>
    </message>
    <message>
        <source>&lt;b&gt;The name &quot;%1&quot; cannot be used.&lt;/b&gt;&lt;p&gt;Try using another name, with fewer characters or no punctuation marks.</source>
        <translation>&lt;b&gt;Ime „%1“ ne može da se upotrebi.&lt;/b&gt;&lt;p&gt;Pokušajte sa drugim imenom, kraćim ili bez znakova interpunkcije.</translation>
    </message>
    <message>
        <source>Date Modified</source>
        <translation>Izmenjeno</translation>
    </message>
</context>
<context>
    <name>QGnomeTheme</name>
    <message>
        <source>&amp;OK</source>
        <translation>&amp;U redu</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Sačuvaj</translation>
    </message>
    <message>
        <source>&amp;Close</source>
        <translation>&amp;Zatvori</translation>
    </message>
    <message>
        <source>Close without Saving</source>
        <translation>Zatvori bez čuvanja</translation>
    </message>
    <message>
        <source>&amp;Cancel</source>
        <translation>&amp;Otkaži</translation>
    </message>
</context>
<context>
    <name>QLineEdit</name>
    <message>
        <source>Cu&amp;t</source>
        <translation>Ise&amp;ci</translation>
    </message>
    <message>
        <source>&amp;Copy</source>
        <translation>&amp;Kopiraj</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Ponovi</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Opozovi</translation>
    </message>
    <message>
        <source>&amp;Paste</source>
        <translation>&amp;Nalepi</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Obriši</translation>
    </message>
    <message>
        <source>Select All</source>
        <translation>Izaberi sve</translation>
    </message>
</context>
<context>
    <name>QPlatformTheme</name>
    <message>
        <source>OK</source>
        <translation>U redu</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Sačuvaj</translation>
    </message>
    <message>
        <source>Save All</source>
        <translation>Sačuvaj sve</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Otvori</translation>
    </message>
    <message>
        <source>&amp;Yes</source>
        <translation>&amp;Da</translation>
    </message>
    <message>
        <source>Yes to &amp;All</source>
        <translation>Da za &amp;sve</translation>
    </message>
    <message>
        <source>&amp;No</source>
        <translation>&amp;Ne</translation>
    </message>
    <message>
        <source>N&amp;o to All</source>
        <translation>N&amp;e za sve</translation>
    </message>
    <message>
        <source>Abort</source>
        <translation>Prekini</translation>
    </message>
    <message>
        <source>Retry</source>
        <translation>Pokušaj ponovo</translation>
    </message>
    <message>
        <source>Ignore</source>
        <translation>Zanemari</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Zatvori</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Otkaži</translation>
    </message>
    <message>
        <source>Discard</source>
        <translation>Odbaci</translation>
    </message>
    <message>
        <source>Help</source>
        <translation>Pomoć</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Primeni</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Poništi</translation>
    </message>
    <message>
        <source>Restore Defaults</source>
        <translation>Vrati podrazumevano</translation>
    </message>
</context>
<context>
    <name>QScrollBar</name>
    <message>
        <source>Top</source>
        <translation>Na vrh</translation>
    </message>
    <message>
        <source>Scroll down</source>
        <translation>Pomeri nadole</translation>
    </message>
    <message>
        <source>Scroll here</source>
        <translation>Pomeri ovde</translation>
    </message>
    <message>
        <source>Scroll left</source>
        <translation>Pomeri ulevo</translation>
    </message>
    <message>
        <source>Bottom</source>
        <translation>Na dno</translation>
    </message>
    <message>
        <source>Page up</source>
        <translation>Strana nagore</translation>
    </message>
    <message>
        <source>Page right</source>
        <translation>Strana udesno</translation>
    </message>
    <message>
        <source>Scroll up</source>
        <translation>Pomeri nagore</translation>
    </message>
    <message>
        <source>Scroll right</source>
        <translation>Pomeri udesno</translation>
    </message>
    <message>
        <source>Left edge</source>
        <translation>Do leve ivice</translation>
    </message>
    <message>
        <source>Page down</source>
        <translation>Strana nadole</translation>
    </message>
    <message>
        <source>Page left</source>
        <translation>Strana ulevo</translation>
    </message>
    <message>
        <source>Right edge</source>
        <translation>Do desne ivice</translation>
    </message>
</context>
<context>
    <name>QTabBar</name>
    <message>
        <source>Scroll Left</source>
        <translation>Pomeri ulevo</translation>
    </message>
    <message>
        <source>Scroll Right</source>
        <translation>Pomeri udesno</translation>
    </message>
</context>
<context>
    <name>QWidgetTextControl</name>
    <message>
        <source>Cu&amp;t</source>
        <translation>Ise&amp;ci</translation>
    </message>
    <message>
        <source>&amp;Copy</source>
        <translation>&amp;Kopiraj</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Ponovi</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Opozovi</translation>
    </message>
    <message>
        <source>&amp;Paste</source>
        <translation>&amp;Nalepi</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Obriši</translation>
    </message>
    <message>
        <source>Select All</source>
        <translation>Izaberi sve</translation>
    </message>
    <message>
        <source>Copy &amp;Link Location</source>
        <translation>Kopiraj &amp;adresu veze</translation>
    </message>
</context>
<context>
    <name>Sheet</name>
    <message>
        <source>frame</source>
        <translation>postolje</translation>
    </message>
    <message>
        <source>crank</source>
        <translation>poluga</translation>
    </message>
    <message>
        <source>coupler</source>
        <translation>spojka</translation>
    </message>
    <message>
        <source>link</source>
        <translation>član</translation>
    </message>
    <message>
        <source>rod</source>
        <translation>šipka</translation>
    </message>
    <message>
        <source>platform</source>
        <translation>platforma</translation>
    </message>
    <message>
        <source>Design parameters</source>
        <translation>Parametri konstrukcije</translation>
    </message>
    <message>
        <source> (derived)</source>
        <translation> (izvedena veličina)</translation>
    </message>
    <message>
        <source>Derived dimensions</source>
        <translation>Izvedene mere</translation>
    </message>
    <message>
        <source>Links and guides (between joint centres)</source>
        <translation>Članovi i vođice (između središta zglobova)</translation>
    </message>
    <message>
        <source>between</source>
        <translation>između</translation>
    </message>
    <message>
        <source>part</source>
        <translation>deo</translation>
    </message>
    <message>
        <source>kind</source>
        <translation>vrsta</translation>
    </message>
    <message>
        <source>length</source>
        <translation>dužina</translation>
    </message>
    <message>
        <source>guide</source>
        <translation>vođica</translation>
    </message>
    <message>
        <source>guide (stroke)</source>
        <translation>vođica (hod)</translation>
    </message>
    <message>
        <source>Ranges of motion</source>
        <translation>Opsezi kretanja</translation>
    </message>
    <message>
        <source>variable</source>
        <translation>promenljiva</translation>
    </message>
    <message>
        <source>role</source>
        <translation>uloga</translation>
    </message>
    <message>
        <source>this pose</source>
        <translation>ovaj položaj</translation>
    </message>
    <message>
        <source>min</source>
        <translation>min</translation>
    </message>
    <message>
        <source>max</source>
        <translation>maks</translation>
    </message>
    <message>
        <source>travel</source>
        <translation>hod</translation>
    </message>
    <message>
        <source>unit</source>
        <translation>jedinica</translation>
    </message>
    <message>
        <source>input (actuated)</source>
        <translation>ulaz (pogonski)</translation>
    </message>
    <message>
        <source>output</source>
        <translation>izlaz</translation>
    </message>
    <message>
        <source>pose</source>
        <translation>položaj</translation>
    </message>
    <message>
        <source>home</source>
        <translation>početni položaj</translation>
    </message>
    <message>
        <source>%1 max</source>
        <translation>%1 maks</translation>
    </message>
    <message>
        <source>%1 min</source>
        <translation>%1 min</translation>
    </message>
    <message>
        <source>Every actuated input at the ends of its range with the others at the home pose, where the mechanism reaches it.</source>
        <translation>Svaki pogonski ulaz na krajevima svog opsega, dok su ostali u početnom položaju — gde mehanizam može da dostigne taj položaj.</translation>
    </message>
    <message>
        <source>No singular pose in the range of motion</source>
        <translation>Nema singularnih položaja u opsegu kretanja</translation>
    </message>
    <message>
        <source>singularity margin ≥ %1</source>
        <translation>margina singulariteta ≥ %1</translation>
    </message>
    <message>
        <source>least at %1 = %2</source>
        <translation>najmanja pri %1 = %2</translation>
    </message>
    <message>
        <source>%1 over %2</source>
        <translation>%1 u zavisnosti od %2</translation>
    </message>
    <message>
        <source>Dimensioned drawing</source>
        <translation>Kotirani crtež</translation>
    </message>
    <message>
        <source>The mechanism in the pose of this sheet, scale %1</source>
        <translation>Mehanizam u položaju ove liste, razmera %1</translation>
    </message>
    <message>
        <source>Pose: %1. Scale %2 on A4 (the scale bar holds on any print size). Lengths in mm, angles in degrees; the dimensions are those of the pose shown.</source>
        <translation>Položaj: %1. Razmera %2 na formatu A4 (grafička razmera važi pri svakoj veličini štampe). Dužine u mm, uglovi u stepenima; mere važe za prikazani položaj.</translation>
    </message>
    <message>
        <source>Design warnings</source>
        <translation>Upozorenja o konstrukciji</translation>
    </message>
    <message>
        <source>Key poses</source>
        <translation>Karakteristični položaji</translation>
    </message>
    <message>
        <source>Checks</source>
        <translation>Provere</translation>
    </message>
    <message>
        <source>Plots</source>
        <translation>Dijagrami</translation>
    </message>
    <message>
        <source>screw beyond the motor body at d_min</source>
        <translation>deo vretena izvan tela motora pri d_min</translation>
    </message>
    <message>
        <source>screw beyond the motor body at d_max (least free screw length)</source>
        <translation>deo vretena izvan tela motora pri d_max (najmanja slobodna dužina vretena)</translation>
    </message>
    <message>
        <source>motor steps per revolution of the screw</source>
        <translation>koraka motora po obrtaju vretena</translation>
    </message>
    <message>
        <source>motor speed at ḋ_max, 60·ḋ_max/h</source>
        <translation>broj obrtaja motora pri ḋ_max, 60·ḋ_max/h</translation>
    </message>
    <message>
        <source>step rate at ḋ_max, ḋ_max/Δd</source>
        <translation>učestanost koraka pri ḋ_max, ḋ_max/Δd</translation>
    </message>
    <message>
        <source>Key poses over the range and the recommended range</source>
        <translation>Karakteristični položaji: opseg kretanja i preporučeni opseg</translation>
    </message>
    <message>
        <source>θ_rec,min</source>
        <translation>θ_rec,min</translation>
    </message>
    <message>
        <source>θ_rec,max</source>
        <translation>θ_rec,max</translation>
    </message>
    <message>
        <source> (this pose)</source>
        <translation> (ovaj položaj)</translation>
    </message>
    <message>
        <source>T at F_max = %1 N, θ̇ at ḋ_max = %2 mm/s, Δθ per motor step Δd = %3 mm. The recommended range keeps J — and with it T, θ̇ and Δθ — within %4 % of its best over the range (the document: θ = −60°…40°).</source>
        <translation>T pri F_max = %1 N, θ̇ pri ḋ_max = %2 mm/s, Δθ po koraku motora Δd = %3 mm. U preporučenom opsegu J — a s njim i T, θ̇ i Δθ — ostaje u granicama od %4 % svoje najbolje vrednosti u opsegu (u dokumentu: θ = −60°…40°).</translation>
    </message>
    <message>
        <source>Actuator check</source>
        <translation>Provera aktuatora</translation>
    </message>
    <message>
        <source>The chosen motor: lead h = %1 mm, step Δd = %2 mm, ḋ_max = %3 mm/s, thrust F_max = %4 N, screw efficiency η = %5; body %6 mm long.</source>
        <translation>Izabrani motor: uspon navoja h = %1 mm, korak Δd = %2 mm, ḋ_max = %3 mm/s, potisna sila F_max = %4 N, stepen iskorišćenja vretena η = %5; dužina tela %6 mm.</translation>
    </message>
    <message>
        <source>Motor body fits the shortest diagonal</source>
        <translation>Telo motora staje u najkraću dijagonalu</translation>
    </message>
    <message>
        <source>stroke d_max − d_min = %1 mm</source>
        <translation>hod d_max − d_min = %1 mm</translation>
    </message>
    <message>
        <source>worst at θ = %1, best at θ = %2; recommended range %3…%4</source>
        <translation>najlošije pri θ = %1, najbolje pri θ = %2; preporučeni opseg %3…%4</translation>
    </message>
    <message>
        <source>Output torque T = J·F_max (13)</source>
        <translation>Izlazni moment T = J·F_max (13)</translation>
    </message>
    <message>
        <source>least T ≥ %1 % of the best</source>
        <translation>najmanji T ≥ %1 % od najvećeg</translation>
    </message>
    <message>
        <source>Output speed θ̇ = ḋ_max/J (8)</source>
        <translation>Izlazna brzina θ̇ = ḋ_max/J (8)</translation>
    </message>
    <message>
        <source>greatest θ̇ ≤ the least ÷ %1</source>
        <translation>najveća θ̇ ≤ najmanja ÷ %1</translation>
    </message>
    <message>
        <source>Output resolution Δθ = Δd/J</source>
        <translation>Izlazna rezolucija Δθ = Δd/J</translation>
    </message>
    <message>
        <source>coarsest Δθ ≤ the finest ÷ %1</source>
        <translation>najgrublje Δθ ≤ najfinije ÷ %1</translation>
    </message>
    <message>
        <source>No singular pose in the range (θ = ±90°)</source>
        <translation>Nema singularnih položaja u opsegu (θ = ±90°)</translation>
    </message>
    <message>
        <source>|cos θ| ≥ %1</source>
        <translation>|cos θ| ≥ %1</translation>
    </message>
    <message>
        <source>Motor torque to push F_max</source>
        <translation>Moment motora potreban za silu F_max</translation>
    </message>
    <message>
        <source>the motor must give it at %1 min⁻¹ (%2 steps/s)</source>
        <translation>motor mora da ga daje pri %1 min⁻¹ (%2 koraka/s)</translation>
    </message>
    <message>
        <source>FAIL above means that the range of θ reaches where J falls steeply: keep the joint in the recommended range %1…%2 where it must give its torque, speed and resolution.</source>
        <translation>„NIJE ISPUNJENO“ iznad znači da opseg θ zalazi u oblast naglog pada J: tamo gde zglob mora da daje svoj moment, brzinu i rezoluciju, držite ga u preporučenom opsegu %1…%2.</translation>
    </message>
    <message>
        <source>Diagonal length d(θ) (2), fig. 8</source>
        <translation>Dužina dijagonale d(θ) (2), sl. 8</translation>
    </message>
    <message>
        <source>Transmission angle μ(θ), fig. 10</source>
        <translation>Ugao prenosa μ(θ), sl. 10</translation>
    </message>
    <message>
        <source>Jacobian J(θ) = ∂d/∂θ (7), fig. 11</source>
        <translation>Jakobijan J(θ) = ∂d/∂θ (7), sl. 11</translation>
    </message>
    <message>
        <source>Output torque T = J·F_max (13), fig. 17</source>
        <translation>Izlazni moment T = J·F_max (13), sl. 17</translation>
    </message>
    <message>
        <source>Output speed θ̇ = ḋ_max/J, fig. 16</source>
        <translation>Izlazna brzina θ̇ = ḋ_max/J, sl. 16</translation>
    </message>
    <message>
        <source>Output resolution Δθ = Δd/J, fig. 15</source>
        <translation>Izlazna rezolucija Δθ = Δd/J, sl. 15</translation>
    </message>
    <message>
        <source>θ (°)</source>
        <translation>θ (°)</translation>
    </message>
    <message>
        <source>beyond the θ range</source>
        <translation>izvan opsega θ</translation>
    </message>
    <message>
        <source>this design (k = %1)</source>
        <translation>ova konstrukcija (k = %1)</translation>
    </message>
    <message>
        <source>recommended range</source>
        <translation>preporučeni opseg</translation>
    </message>
    <message>
        <source>steep region</source>
        <translation>strma oblast</translation>
    </message>
    <message>
        <source>a = %1 mm; the family k = 0.3 … 1.5 at the same a</source>
        <translation>a = %1 mm; familija k = 0,3 … 1,5 pri istom a</translation>
    </message>
    <message>
        <source>crank-rocker</source>
        <translation>poluga–klackalica</translation>
    </message>
    <message>
        <source>rocker-crank</source>
        <translation>klackalica–poluga</translation>
    </message>
    <message>
        <source>double-crank</source>
        <translation>dvostruka poluga</translation>
    </message>
    <message>
        <source>double-rocker</source>
        <translation>dvostruka klackalica</translation>
    </message>
    <message>
        <source>triple-rocker (non-Grashof)</source>
        <translation>trostruka klackalica (nije po Grashofu)</translation>
    </message>
    <message>
        <source>change-point</source>
        <translation>prelazni</translation>
    </message>
    <message>
        <source>class</source>
        <translation>klasa</translation>
    </message>
    <message>
        <source>Grashof class, s + l against p + q</source>
        <translation>klasa po Grashofu: s + l u odnosu na p + q</translation>
    </message>
    <message>
        <source>shortest + longest link</source>
        <translation>najkraći + najduži član</translation>
    </message>
    <message>
        <source>the other two links</source>
        <translation>druga dva člana</translation>
    </message>
    <message>
        <source>Key poses over the crank angle</source>
        <translation>Karakteristični položaji po uglu poluge</translation>
    </message>
    <message>
        <source>least μ</source>
        <translation>najmanji μ</translation>
    </message>
    <message>
        <source>At the constant crank speed ω₁ = %1 rad/s.</source>
        <translation>Pri stalnoj ugaonoj brzini poluge ω₁ = %1 rad/s.</translation>
    </message>
    <message>
        <source>Design check</source>
        <translation>Provera konstrukcije</translation>
    </message>
    <message>
        <source>Grashof class</source>
        <translation>Klasa po Grashofu</translation>
    </message>
    <message>
        <source>s + l = %1 mm, p + q = %2 mm</source>
        <translation>s + l = %1 mm; p + q = %2 mm</translation>
    </message>
    <message>
        <source>Crank angle range</source>
        <translation>Opseg ugla poluge</translation>
    </message>
    <message>
        <source>the crank AB turns fully</source>
        <translation>poluga AB se obrće pun krug</translation>
    </message>
    <message>
        <source>the crank AB cannot turn fully</source>
        <translation>poluga AB ne može da se obrne pun krug</translation>
    </message>
    <message>
        <source>Least transmission angle over the range</source>
        <translation>Najmanji ugao prenosa u opsegu</translation>
    </message>
    <message>
        <source>at α = %1°</source>
        <translation>pri α = %1°</translation>
    </message>
    <message>
        <source>Rocker angle δ(α)</source>
        <translation>Ugao klackalice δ(α)</translation>
    </message>
    <message>
        <source>Transmission angle μ(α)</source>
        <translation>Ugao prenosa μ(α)</translation>
    </message>
    <message>
        <source>Rocker angular velocity ω₃(α)</source>
        <translation>Ugaona brzina klackalice ω₃(α)</translation>
    </message>
    <message>
        <source>Rocker angular acceleration ε₃(α)</source>
        <translation>Ugaono ubrzanje klackalice ε₃(α)</translation>
    </message>
    <message>
        <source>μ = %1°: poor below</source>
        <translation>μ = %1°: ispod toga loš prenos</translation>
    </message>
    <message>
        <source>none</source>
        <translation>nema</translation>
    </message>
    <message>
        <source>inverse</source>
        <translation>inverzni</translation>
    </message>
    <message>
        <source>direct</source>
        <translation>direktni</translation>
    </message>
    <message>
        <source>combined</source>
        <translation>kombinovani</translation>
    </message>
    <message>
        <source>PASS</source>
        <translation>ISPUNJENO</translation>
    </message>
    <message>
        <source>FAIL</source>
        <translation>NIJE ISPUNJENO</translation>
    </message>
    <message>
        <source>INFO</source>
        <translation>INFO</translation>
    </message>
    <message>
        <source>singularity</source>
        <translation>singularitet</translation>
    </message>
    <message>
        <source>singularity class of the pose</source>
        <translation>vrsta singulariteta u tom položaju</translation>
    </message>
    <message>
        <source>PKM Studio · Parameter sheet</source>
        <translation>PKM Studio · Lista parametara</translation>
    </message>
    <message>
        <source>page %1 of %2</source>
        <translation>strana %1 od %2</translation>
    </message>
    <message>
        <source>Parameter sheet</source>
        <translation>Lista parametara</translation>
    </message>
    <message>
        <source>field</source>
        <translation>polje</translation>
    </message>
    <message>
        <source>value</source>
        <translation>vrednost</translation>
    </message>
    <message>
        <source>Design</source>
        <translation>Konstrukcija</translation>
    </message>
    <message>
        <source>Mechanism</source>
        <translation>Mehanizam</translation>
    </message>
    <message>
        <source>Pose</source>
        <translation>Položaj</translation>
    </message>
    <message>
        <source>Date</source>
        <translation>Datum</translation>
    </message>
    <message>
        <source>Software</source>
        <translation>Program</translation>
    </message>
    <message>
        <source>About</source>
        <translation>Opis</translation>
    </message>
    <message>
        <source>Units: lengths mm, angles degrees, forces N, torques N·m, times s, unless a column says otherwise.</source>
        <translation>Jedinice: dužine u mm, uglovi u stepenima, sile u N, momenti u N·m, vreme u s, osim ako u koloni ne piše drugačije.</translation>
    </message>
    <message>
        <source>Geometry</source>
        <translation>Geometrija</translation>
    </message>
    <message>
        <source>Range of motion</source>
        <translation>Opseg kretanja</translation>
    </message>
    <message>
        <source>Actuator</source>
        <translation>Aktuator</translation>
    </message>
    <message>
        <source>Drawing only</source>
        <translation>Samo za crtež</translation>
    </message>
    <message>
        <source>Working and assembly modes</source>
        <translation>Radni režimi i načini sklapanja</translation>
    </message>
    <message>
        <source>symbol</source>
        <translation>oznaka</translation>
    </message>
    <message>
        <source>quantity</source>
        <translation>veličina</translation>
    </message>
    <message>
        <source>key</source>
        <translation>ključ</translation>
    </message>
    <message>
        <source>check</source>
        <translation>provera</translation>
    </message>
    <message>
        <source>limit</source>
        <translation>granica</translation>
    </message>
    <message>
        <source>result</source>
        <translation>rezultat</translation>
    </message>
    <message>
        <source>x (mm)</source>
        <translation>x (mm)</translation>
    </message>
    <message>
        <source>y (mm)</source>
        <translation>y (mm)</translation>
    </message>
    <message>
        <source>scale (A4)</source>
        <translation>razmera (A4)</translation>
    </message>
    <message>
        <source>scale bar</source>
        <translation>grafička razmera</translation>
    </message>
    <message>
        <source>units</source>
        <translation>jedinice</translation>
    </message>
    <message>
        <source>mm, degrees</source>
        <translation>mm, stepeni</translation>
    </message>
    <message>
        <source>design</source>
        <translation>konstrukcija</translation>
    </message>
    <message>
        <source>date</source>
        <translation>datum</translation>
    </message>
    <message>
        <source>Parameter sheet: %1</source>
        <translation>Lista parametara: %1</translation>
    </message>
    <message>
        <source>Workspace</source>
        <translation>Radni prostor</translation>
    </message>
    <message>
        <source>The platform positions reachable with every actuated input inside its range%1, on a grid of %2 × %3 square cells of %4 mm (as &apos;pkm workspace --grid %5&apos;).</source>
        <translation>Položaji platforme dostižni kada je svaki pogonski ulaz unutar svog opsega%1, na mreži od %2 × %3 kvadratnih ćelija stranice %4 mm (kao &apos;pkm workspace --grid %5&apos;).</translation>
    </message>
    <message>
        <source>area of this form&apos;s workspace (exact)</source>
        <translation>površina radnog prostora ovog oblika (tačno)</translation>
    </message>
    <message>
        <source>area of the extended (O) form (exact)</source>
        <translation>površina za opruženi (O) oblik (tačno)</translation>
    </message>
    <message>
        <source>area of the crossed (X) form (exact)</source>
        <translation>površina za ukršteni (X) oblik (tačno)</translation>
    </message>
    <message>
        <source>area of this form on the grid</source>
        <translation>površina ovog oblika na mreži</translation>
    </message>
    <message>
        <source>area of the workspace (grid)</source>
        <translation>površina radnog prostora (po mreži)</translation>
    </message>
    <message>
        <source>area in mode %1 (grid)</source>
        <translation>površina u režimu %1 (po mreži)</translation>
    </message>
    <message>
        <source>area of the union of all modes (grid)</source>
        <translation>površina unije svih režima (po mreži)</translation>
    </message>
    <message>
        <source>travel of the carrying axis</source>
        <translation>hod noseće ose</translation>
    </message>
    <message>
        <source>volume: the area extruded over the travel</source>
        <translation>zapremina: površina izvučena duž hoda</translation>
    </message>
    <message>
        <source>reachable cells from x</source>
        <translation>dostižne ćelije od x</translation>
    </message>
    <message>
        <source>reachable cells to x</source>
        <translation>dostižne ćelije do x</translation>
    </message>
    <message>
        <source>reachable cells from y</source>
        <translation>dostižne ćelije od y</translation>
    </message>
    <message>
        <source>reachable cells to y</source>
        <translation>dostižne ćelije do y</translation>
    </message>
    <message>
        <source>cells</source>
        <translation>ćelije</translation>
    </message>
    <message>
        <source>reachable cells of the grid</source>
        <translation>dostižne ćelije mreže</translation>
    </message>
    <message>
        <source>Area per working and assembly mode</source>
        <translation>Površina po radnim režimima i načinima sklapanja</translation>
    </message>
    <message>
        <source>mode</source>
        <translation>mod</translation>
    </message>
    <message>
        <source>area (grid)</source>
        <translation>površina (po mreži)</translation>
    </message>
    <message>
        <source>area (exact)</source>
        <translation>površina (tačno)</translation>
    </message>
    <message>
        <source>note</source>
        <translation>napomena</translation>
    </message>
    <message>
        <source>this design</source>
        <translation>ova konstrukcija</translation>
    </message>
    <message>
        <source>no workspace</source>
        <translation>nema radnog prostora</translation>
    </message>
    <message>
        <source>Workspaces of the modes</source>
        <translation>Radni prostori po režimima</translation>
    </message>
    <message>
        <source>As &apos;pkm workspace -o FILE.png&apos;: this design&apos;s mode dark blue over the others&apos; light blue, the outline of their union dark.</source>
        <translation>Kao &apos;pkm workspace -o FILE.png&apos;: režim ove konstrukcije tamnoplavo preko ostalih (svetloplavo), obris njihove unije tamno.</translation>
    </message>
    <message>
        <source>As &apos;pkm workspace -o FILE.png&apos;: the reachable cells light blue with a dark outline.</source>
        <translation>Kao &apos;pkm workspace -o FILE.png&apos;: dostižne ćelije svetloplavo, sa tamnim obrisom.</translation>
    </message>
    <message>
        <source>Singularity map: det J</source>
        <translation>Mapa singulariteta: det J</translation>
    </message>
    <message>
        <source>As &apos;pkm map -o FILE.png&apos;: det J blue below 0, white at 0 (a direct singularity), red above 0, clipped at ±%1; the inverse singular curves dark red, the direct ones dashed.</source>
        <translation>Kao &apos;pkm map -o FILE.png&apos;: det J plavo ispod 0, belo u 0 (direktni singularitet), crveno iznad 0, odsečeno na ±%1; inverzne singularne krive tamnocrvene, direktne isprekidane.</translation>
    </message>
    <message>
        <source>Singular poses in the workspace</source>
        <translation>Singularni položaji u radnom prostoru</translation>
    </message>
    <message>
        <source>near-singular cells (margin &lt; %1, about 3° from a singular pose)</source>
        <translation>ćelije blizu singulariteta (margina &lt; %1, oko 3° od singularnog položaja)</translation>
    </message>
    <message>
        <source>their area</source>
        <translation>njihova površina</translation>
    </message>
    <message>
        <source>Singular curves, each with one of its poses</source>
        <translation>Singularne krive, svaka sa jednim od svojih položaja</translation>
    </message>
    <message>
        <source>where</source>
        <translation>gde</translation>
    </message>
    <message>
        <source>type</source>
        <translation>vrsta</translation>
    </message>
    <message>
        <source>curve length</source>
        <translation>dužina krive</translation>
    </message>
    <message>
        <source>Inverse: a leg loses a degree of freedom (a link perpendicular to its guide); direct: the platform gains one (the links in line). The pose given is the middle of each curve.</source>
        <translation>Inverzni: kinematički lanac gubi jedan stepen slobode (član upravan na svoju vođicu); direktni: platforma dobija jedan stepen slobode (članovi u istoj liniji). Dati položaj je sredina svake krive.</translation>
    </message>
    <message>
        <source>No singular curve lies inside the workspace.</source>
        <translation>Nijedna singularna kriva ne leži unutar radnog prostora.</translation>
    </message>
    <message>
        <source>Stroke of %1 the workspace uses</source>
        <translation>Hod %1 koji koristi radni prostor</translation>
    </message>
    <message>
        <source>within the guide %1 … %2</source>
        <translation>unutar vođice %1 … %2</translation>
    </message>
    <message>
        <source>within its range %1 … %2</source>
        <translation>unutar svog opsega %1 … %2</translation>
    </message>
    <message>
        <source>used from %1 to %2</source>
        <translation>koristi se od %1 do %2</translation>
    </message>
    <message>
        <source>Direct singular poses in the workspace</source>
        <translation>Direktni singularni položaji u radnom prostoru</translation>
    </message>
    <message>
        <source>Inverse singular poses in the workspace</source>
        <translation>Inverzni singularni položaji u radnom prostoru</translation>
    </message>
    <message>
        <source>none: the platform would move with the actuators locked</source>
        <translation>ne sme ih biti: platforma bi se pomerala sa zakočenim aktuatorima</translation>
    </message>
    <message>
        <source>where a leg reaches the end of its reach; keep away in use</source>
        <translation>gde kinematički lanac dostiže kraj svog dometa; u radu se držati dalje od njih</translation>
    </message>
    <message>
        <source>no singular curve of this kind</source>
        <translation>nema singularnih krivih ove vrste</translation>
    </message>
    <message>
        <source>α ∈ [%1°, %2°]</source>
        <translation>α ∈ [%1°; %2°]</translation>
    </message>
    <message>
        <source>min⁻¹</source>
        <translation>min⁻¹</translation>
    </message>
    <message>
        <source>steps/s</source>
        <translation>koraka/s</translation>
    </message>
    <message>
        <source>mm³</source>
        <translation>mm³</translation>
    </message>
    <message>
        <source>Actuator capability</source>
        <translation>Mogućnosti pogona</translation>
    </message>
    <message>
        <source>What the actuators deliver at the platform at this pose, every actuator within its limits: the force and the speed in the weakest and the strongest direction, the error from half a step per actuator and the stiffness from the actuators alone.</source>
        <translation>Šta pogoni daju na platformi u ovom položaju, svaki u svojim granicama: sila i brzina u najslabijem i najjačem pravcu, greška od pola koraka svakog pogona i krutost od samih pogona.</translation>
    </message>
    <message>
        <source>The actuator&apos;s axial stiffness is an assumed value (about 20 N/µm for a small lead screw with its nut and bearings): Table 1 gives none.</source>
        <translation>Aksijalna krutost pogona je pretpostavljena (oko 20 N/µm za malo navojno vreteno s navrtkom i ležajevima): tabela 1 je ne daje.</translation>
    </message>
    <message>
        <source>Actuator values left at their defaults are assumed, plausible ones (a NEMA 17 stepper with a 5:1 gearbox, a small lead-screw slide): the source documents give none.</source>
        <translation>Vrednosti pogona ostavljene na podrazumevanim su pretpostavljene, uverljive (koračni motor NEMA 17 s reduktorom 5:1, mali klizač s navojnim vretenom): izvorni dokumenti ih ne daju.</translation>
    </message>
    <message>
        <source>The actuator alone would make the joint %1 N·m/rad stiff here; the measured %2 N·m/rad is lower because the hinges, links and frame yield in series with it (1/K = 1/K_actuator + 1/K_rest): together they are about %3 N·m/rad.</source>
        <translation>Sam pogon bi ovde zglobu dao krutost %1 N·m/rad; izmerenih %2 N·m/rad je manje jer zglobovi, članci i ram popuštaju redno s njim (1/K = 1/K_pogona + 1/K_ostalo): zajedno daju oko %3 N·m/rad.</translation>
    </message>
    <message>
        <source>The actuator alone gives %1 N·m/rad here, less than the measured %2 N·m/rad of the whole joint: the assumed axial stiffness of the actuator is too low for the measurement, or the pose is near a singularity where the actuator cannot hold the output.</source>
        <translation>Sam pogon ovde daje %1 N·m/rad, manje od izmerenih %2 N·m/rad celog zgloba: pretpostavljena aksijalna krutost pogona je premala za merenje, ili je položaj blizu singularnog, gde pogon ne drži izlaz.</translation>
    </message>
    <message>
        <source>The actuators hold the design&apos;s load at this pose</source>
        <translation>Pogoni drže opterećenje konstrukcije u ovom položaju</translation>
    </message>
    <message>
        <source>max |τ_i| / τ_max,i ≤ 1</source>
        <translation>max |τ_i| / τ_max,i ≤ 1</translation>
    </message>
    <message>
        <source>no load</source>
        <translation>nema opterećenja</translation>
    </message>
    <message>
        <source>The design states no load (load_x, load_y, load_moment or load_torque in the actuator group).</source>
        <translation>Konstrukcija ne zadaje opterećenje (load_x, load_y, load_moment ili load_torque u grupi pogona).</translation>
    </message>
    <message>
        <source>actuator %1 at %2 % of its limit</source>
        <translation>pogon %1 na %2 % svoje granice</translation>
    </message>
    <message>
        <source>at a direct singularity no effort of the actuators holds a load</source>
        <translation>u singularitetu direktne kinematike nijedan napor pogona ne drži opterećenje</translation>
    </message>
    <message>
        <source>Required at this pose: %1</source>
        <translation>Zahteva se u ovom položaju: %1</translation>
    </message>
    <message>
        <source>undefined</source>
        <translation>nedefinisano</translation>
    </message>
    <message>
        <source>Every requirement holds over the whole workspace</source>
        <translation>Svi zahtevi ispunjeni u celom radnom prostoru</translation>
    </message>
    <message>
        <source>area met = workspace area</source>
        <translation>površina ispunjenja = površina radnog prostora</translation>
    </message>
    <message>
        <source>met in %1 mm² of %2 mm² (grid of %3 × %4 cells)</source>
        <translation>ispunjeni na %1 mm² od %2 mm² (mreža od %3 × %4 ćelija)</translation>
    </message>
</context>
<context>
    <name>core</name>
    <message>
        <source>The rank counts the platform&apos;s x and y, the carriage&apos;s z and the platform&apos;s tilt (its swing about the longitudinal axis). The actuators drive x_AB, x_CD and z; the tilt is not held by them. With the joints the document describes (spherical at the platform, one hinge per rod at the slider, a pair&apos;s rods one behind the other) the platform can tilt with the sliders locked; the document&apos;s kinematics assume it stays level.</source>
        <translation>Rang obuhvata x i y platforme, z kolica i nagib platforme (njeno ljuljanje oko podužne ose). Pogoni zadaju x_AB, x_CD i z; nagib oni ne drže. Sa zglobovima koje rad opisuje (sferni kod platforme, po jedan zglob za svaki štap kod klizača, štapovi jednog para jedan iza drugog) platforma može da se nagne sa zakočenim klizačima; kinematika iz rada pretpostavlja da platforma ostaje vodoravna.</translation>
    </message>
    <message>
        <source>%1 mm</source>
        <translation>%1 mm</translation>
    </message>
    <message>
        <source>mm</source>
        <translation>mm</translation>
    </message>
    <message>
        <source>mm²</source>
        <translation>mm²</translation>
    </message>
    <message>
        <source>N</source>
        <translation>N</translation>
    </message>
    <message>
        <source>N·m</source>
        <translation>N·m</translation>
    </message>
    <message>
        <source>mm/s</source>
        <translation>mm/s</translation>
    </message>
    <message>
        <source>rad/s</source>
        <translation>rad/s</translation>
    </message>
    <message>
        <source>mm/rad</source>
        <translation>mm/rad</translation>
    </message>
    <message>
        <source>mm/rad²</source>
        <translation>mm/rad²</translation>
    </message>
    <message>
        <source>mm²/rad</source>
        <translation>mm²/rad</translation>
    </message>
    <message>
        <source>rad/mm</source>
        <translation>rad/mm</translation>
    </message>
    <message>
        <source>mm/rev</source>
        <translation>mm/obr</translation>
    </message>
    <message>
        <source>mm/step</source>
        <translation>mm/korak</translation>
    </message>
    <message>
        <source>°/step</source>
        <translation>°/korak</translation>
    </message>
    <message>
        <source>N·m/rad</source>
        <translation>N·m/rad</translation>
    </message>
    <message>
        <source>mm⁴</source>
        <translation>mm⁴</translation>
    </message>
    <message>
        <source>rad²/mm²</source>
        <translation>rad²/mm²</translation>
    </message>
    <message>
        <source>(%1, %2) mm</source>
        <translation>(%1; %2) mm</translation>
    </message>
    <message>
        <source>[%1, %2]</source>
        <translation>[%1; %2]</translation>
    </message>
    <message>
        <source>%1 right of %2</source>
        <translation>%1 desno od %2</translation>
    </message>
    <message>
        <source>%1 left of %2</source>
        <translation>%1 levo od %2</translation>
    </message>
    <message>
        <source>length of crank 1, driven at A</source>
        <translation>dužina poluge 1 (pogon u A)</translation>
    </message>
    <message>
        <source>length of distal link 1, from B to C</source>
        <translation>dužina spojke 1, od B do C</translation>
    </message>
    <message>
        <source>length of distal link 2, from C to D</source>
        <translation>dužina spojke 2, od C do D</translation>
    </message>
    <message>
        <source>length of crank 2, driven at E</source>
        <translation>dužina poluge 2 (pogon u E)</translation>
    </message>
    <message>
        <source>length of the ground, from A to E along +x</source>
        <translation>dužina postolja, od A do E duž +x</translation>
    </message>
    <message>
        <source>lower limit of crank angle θ₁</source>
        <translation>donja granica ugla poluge θ₁</translation>
    </message>
    <message>
        <source>upper limit of crank angle θ₁</source>
        <translation>gornja granica ugla poluge θ₁</translation>
    </message>
    <message>
        <source>lower limit of crank angle θ₄</source>
        <translation>donja granica ugla poluge θ₄</translation>
    </message>
    <message>
        <source>upper limit of crank angle θ₄</source>
        <translation>gornja granica ugla poluge θ₄</translation>
    </message>
    <message>
        <source>left</source>
        <translation>levo</translation>
    </message>
    <message>
        <source>right</source>
        <translation>desno</translation>
    </message>
    <message>
        <source>working mode of leg 1: elbow B left (+1) or right (−1) of A→C</source>
        <translation>radni režim noge 1: zglob B levo (+1) ili desno (−1) od A→C</translation>
    </message>
    <message>
        <source>working mode of leg 2: elbow D left (+1) or right (−1) of E→C</source>
        <translation>radni režim noge 2: zglob D levo (+1) ili desno (−1) od E→C</translation>
    </message>
    <message>
        <source>assembly mode: C left (+1) or right (−1) of B→D</source>
        <translation>način sklapanja: C levo (+1) ili desno (−1) od B→D</translation>
    </message>
    <message>
        <source>%1 = %2 is invalid: it must be +1 (left) or -1 (right).</source>
        <translation>%1 = %2 nije dozvoljena vrednost: mora biti +1 (levo) ili -1 (desno).</translation>
    </message>
    <message>
        <source>The five-bar linkage has no parameter named &apos;%1&apos;.</source>
        <translation>Zglobni petougao nema parametar „%1“.</translation>
    </message>
    <message>
        <source>%1 = %2 must be less than %3 = %4.</source>
        <translation>%1 = %2 mora biti manje od %3 = %4.</translation>
    </message>
    <message>
        <source>%1 = %2 lies %3 above %4 = %5: a crank&apos;s range may span one turn (360°) at most.</source>
        <translation>%1 = %2 je za %3 iznad %4 = %5: opseg poluge može da obuhvati najviše jedan obrt (360°).</translation>
    </message>
    <message>
        <source>%1 = %2 is not shorter than %3 = %4: the links cannot close the loop ABCDE for any crank angles (each link must be shorter than the other four together).</source>
        <translation>%1 = %2 nije kraće od %3 = %4: članovi ne mogu da zatvore konturu ABCDE ni za koje uglove poluga (svaki član mora biti kraći od zbira ostala četiri).</translation>
    </message>
    <message>
        <source>This five-bar has no workspace: with %1 the loop ABCDE never closes. Change a mode, a range or a length.</source>
        <translation>Ovaj zglobni petougao nema radni prostor: sa %1 kontura ABCDE se nikada ne zatvara. Promenite mod, opseg ili dužinu.</translation>
    </message>
    <message>
        <source>This five-bar has no workspace: with %1 and the crank ranges %2 the loop ABCDE never closes. Change a mode, a range or a length.</source>
        <translation>Ovaj zglobni petougao nema radni prostor: sa %1 i opsezima poluga %2 kontura ABCDE se nikada ne zatvara. Promenite mod, opseg ili dužinu.</translation>
    </message>
    <message>
        <source>The workspace of these modes reaches direct singularities (the curves where the distal links BC and CD come in line, marked on the map): there C can move with both cranks held and the mechanism may switch its assembly mode. Keep the path of C away from them.</source>
        <translation>Radni prostor ovih režima doseže singularitete direktne kinematike (krive na kojima spojke BC i CD dolaze na istu pravu, označene na mapi): tu se C može pomerati i kad su obe poluge zakočene, a mehanizam može da promeni način sklapanja. Držite putanju tačke C dalje od njih.</translation>
    </message>
    <message>
        <source>crank AB angle at A, from +x counter-clockwise (actuated)</source>
        <translation>ugao poluge AB u A, od +x suprotno smeru kazaljke na satu (pogonska koordinata)</translation>
    </message>
    <message>
        <source>crank ED angle at E, from +x counter-clockwise (actuated)</source>
        <translation>ugao poluge ED u E, od +x suprotno smeru kazaljke na satu (pogonska koordinata)</translation>
    </message>
    <message>
        <source>output point C, x</source>
        <translation>izlazna tačka C, x</translation>
    </message>
    <message>
        <source>output point C, y</source>
        <translation>izlazna tačka C, y</translation>
    </message>
    <message>
        <source>At theta1 = %1, theta4 = %2 the distal links cannot meet: |BD| = %3 is more than BC + CD = %4 (past the dead point where BC and CD are stretched in line, a direct singularity).</source>
        <translation>Pri theta1 = %1, theta4 = %2 spojke ne mogu da se spoje: |BD| = %3 je veće od BC + CD = %4 (iza mrtve tačke u kojoj su BC i CD opružene na istoj pravoj, singulariteta direktne kinematike).</translation>
    </message>
    <message>
        <source>At theta1 = %1, theta4 = %2 the distal links cannot meet: |BD| = %3 is less than |BC − CD| = %4 (past the dead point where BC and CD fold in line, a direct singularity).</source>
        <translation>Pri theta1 = %1, theta4 = %2 spojke ne mogu da se spoje: |BD| = %3 je manje od |BC − CD| = %4 (iza mrtve tačke u kojoj se BC i CD presavijaju na istoj pravoj, singulariteta direktne kinematike).</translation>
    </message>
    <message>
        <source>At theta1 = %1, theta4 = %2 the elbows B and D coincide and BC = CD: the position of C is undetermined.</source>
        <translation>Pri theta1 = %1, theta4 = %2 zglobovi B i D se poklapaju, a BC = CD: položaj C nije određen.</translation>
    </message>
    <message>
        <source>At theta1 = %1, theta4 = %2 leg %3 would be in its other working mode (%4): crank %5 and link %6 pass through in line (an inverse singularity) on the way; switch %7 to go on.</source>
        <translation>Pri theta1 = %1, theta4 = %2 noga %3 bi bila u drugom radnom režimu (%4): poluga %5 i spojka %6 usput prolaze kroz položaj na istoj pravoj (singularitet inverzne kinematike); promenite %7 da biste nastavili.</translation>
    </message>
    <message>
        <source>C cannot reach %1: it lies %2 from %3, more than %4 + %5 = %6.</source>
        <translation>C ne može da stigne do tačke %1: ona je na %2 od %3, više od %4 + %5 = %6.</translation>
    </message>
    <message>
        <source>C cannot reach %1: it lies %2 from %3, less than |%4 − %5| = %6.</source>
        <translation>C ne može da stigne do tačke %1: ona je na %2 od %3, manje od |%4 − %5| = %6.</translation>
    </message>
    <message>
        <source>C = %1 lies on %2 and %3 = %4: the crank angle %5 is undetermined.</source>
        <translation>C = %1 se poklapa sa %2, a %3 = %4: ugao poluge %5 nije određen.</translation>
    </message>
    <message>
        <source>C cannot reach %1: crank %2 would have to be at %3 = %4, outside its range %5.</source>
        <translation>C ne može da stigne do tačke %1: poluga %2 bi morala da bude na %3 = %4, van svog opsega %5.</translation>
    </message>
    <message>
        <source>No failure.</source>
        <translation>Nema greške.</translation>
    </message>
    <message>
        <source>%1 must be a finite number.</source>
        <translation>%1 mora biti konačan broj.</translation>
    </message>
    <message>
        <source>%1 = %2 is outside the range of crank %3, %4: the crank turns fully, give its angle within it.</source>
        <translation>%1 = %2 je van opsega poluge %3, %4: poluga se okreće punim krugom, zadajte ugao unutar tog opsega.</translation>
    </message>
    <message>
        <source>%1 = %2 is outside the range of crank %3, %4.</source>
        <translation>%1 = %2 je van opsega poluge %3, %4.</translation>
    </message>
    <message>
        <source>crank AB angle at A, from +x counter-clockwise</source>
        <translation>ugao poluge AB u A, od +x suprotno smeru kazaljke na satu</translation>
    </message>
    <message>
        <source>crank ED angle at E, from +x counter-clockwise</source>
        <translation>ugao poluge ED u E, od +x suprotno smeru kazaljke na satu</translation>
    </message>
    <message>
        <source>J_x rows (C − B)ᵀ, (C − D)ᵀ</source>
        <translation>vrste J_x: (C − B)ᵀ, (C − D)ᵀ</translation>
    </message>
    <message>
        <source>determinant of J (0: direct, ∞: inverse singularity)</source>
        <translation>determinanta J (0: singularitet direktne, ∞: inverzne kinematike)</translation>
    </message>
    <message>
        <source>0 at an inverse singularity (a leg stretched or folded)</source>
        <translation>0 u singularitetu inverzne kinematike (noga opružena ili presavijena)</translation>
    </message>
    <message>
        <source>0 at a direct singularity (the distal links in line)</source>
        <translation>0 u singularitetu direktne kinematike (spojke na istoj pravoj)</translation>
    </message>
    <message>
        <source>condition number of J</source>
        <translation>broj uslovljenosti J</translation>
    </message>
    <message>
        <source>angle ABC between crank AB and link BC (0°, 180°: inverse singularity)</source>
        <translation>ugao ABC između poluge AB i spojke BC (0°, 180°: singularitet inverzne kinematike)</translation>
    </message>
    <message>
        <source>angle EDC between crank ED and link DC (0°, 180°: inverse singularity)</source>
        <translation>ugao EDC između poluge ED i spojke DC (0°, 180°: singularitet inverzne kinematike)</translation>
    </message>
    <message>
        <source>angle BCD between the distal links (0°, 180°: direct singularity)</source>
        <translation>ugao BCD između spojki (0°, 180°: singularitet direktne kinematike)</translation>
    </message>
    <message>
        <source>transmission angle between the distal links, min(ψ, 180° − ψ)</source>
        <translation>ugao prenosa između spojki, min(ψ, 180° − ψ)</translation>
    </message>
    <message>
        <source>distance from the inverse singularities, min |sin φ_i| (0 … 1)</source>
        <translation>udaljenost od singulariteta inverzne kinematike, min |sin φ_i| (0 … 1)</translation>
    </message>
    <message>
        <source>distance from the direct singularities, |sin ψ| (0 … 1)</source>
        <translation>udaljenost od singulariteta direktne kinematike, |sin ψ| (0 … 1)</translation>
    </message>
    <message>
        <source>distance from the nearest singularity (0 … 1)</source>
        <translation>udaljenost od najbližeg singulariteta (0 … 1)</translation>
    </message>
    <message>
        <source>other assembly mode (C right of B→D, same crank angles)</source>
        <translation>drugi način sklapanja (C desno od B→D, isti uglovi poluga)</translation>
    </message>
    <message>
        <source>other assembly mode (C left of B→D, same crank angles)</source>
        <translation>drugi način sklapanja (C levo od B→D, isti uglovi poluga)</translation>
    </message>
    <message>
        <source>leg 1: other working mode (B left of A→C, same C)</source>
        <translation>noga 1: drugi radni režim (B levo od A→C, ista tačka C)</translation>
    </message>
    <message>
        <source>leg 1: other working mode (B right of A→C, same C)</source>
        <translation>noga 1: drugi radni režim (B desno od A→C, ista tačka C)</translation>
    </message>
    <message>
        <source>leg 2: other working mode (D left of E→C, same C)</source>
        <translation>noga 2: drugi radni režim (D levo od E→C, ista tačka C)</translation>
    </message>
    <message>
        <source>leg 2: other working mode (D right of E→C, same C)</source>
        <translation>noga 2: drugi radni režim (D desno od E→C, ista tačka C)</translation>
    </message>
    <message>
        <source>ground</source>
        <translation>postolje</translation>
    </message>
    <message>
        <source>crank AB</source>
        <translation>poluga AB</translation>
    </message>
    <message>
        <source>link BC</source>
        <translation>spojka BC</translation>
    </message>
    <message>
        <source>link CD</source>
        <translation>spojka CD</translation>
    </message>
    <message>
        <source>crank DE</source>
        <translation>poluga DE</translation>
    </message>
    <message>
        <source>planar five-bar: ground AE, cranks AB and DE (driven at A and E), distal links BC and CD</source>
        <translation>ravanski zglobni petougao: postolje AE, poluge AB i DE (pogon u A i E), spojke BC i CD</translation>
    </message>
    <message>
        <source>drag to move C (inverse kinematics)</source>
        <translation>prevucite da biste pomerili C (inverzna kinematika)</translation>
    </message>
    <message>
        <source>drag to turn crank AB (sets θ₁, direct kinematics)</source>
        <translation>prevucite da biste zaokrenuli polugu AB (zadaje θ₁, direktna kinematika)</translation>
    </message>
    <message>
        <source>drag to turn crank DE (sets θ₄, direct kinematics)</source>
        <translation>prevucite da biste zaokrenuli polugu DE (zadaje θ₄, direktna kinematika)</translation>
    </message>
    <message>
        <source>No handle with that index.</source>
        <translation>Nema ručice sa tim indeksom.</translation>
    </message>
    <message>
        <source>crank and distal link in line</source>
        <translation>poluga i spojka na istoj pravoj</translation>
    </message>
    <message>
        <source>distal links in line</source>
        <translation>spojke na istoj pravoj</translation>
    </message>
    <message>
        <source>leg 1 stretched (AB, BC in line)</source>
        <translation>noga 1 opružena (AB, BC na istoj pravoj)</translation>
    </message>
    <message>
        <source>leg 1 folded (AB, BC in line)</source>
        <translation>noga 1 presavijena (AB, BC na istoj pravoj)</translation>
    </message>
    <message>
        <source>leg 2 stretched (DE, CD in line)</source>
        <translation>noga 2 opružena (DE, CD na istoj pravoj)</translation>
    </message>
    <message>
        <source>leg 2 folded (DE, CD in line)</source>
        <translation>noga 2 presavijena (DE, CD na istoj pravoj)</translation>
    </message>
    <message>
        <source>rad/s²</source>
        <translation>rad/s²</translation>
    </message>
    <message>
        <source>crossed</source>
        <translation>ukrštena</translation>
    </message>
    <message>
        <source>open</source>
        <translation>otvorena</translation>
    </message>
    <message>
        <source>crank-rocker</source>
        <translation>poluga–klackalica</translation>
    </message>
    <message>
        <source>rocker-crank</source>
        <translation>klackalica–poluga</translation>
    </message>
    <message>
        <source>double-crank</source>
        <translation>dvostruka poluga</translation>
    </message>
    <message>
        <source>double-rocker</source>
        <translation>dvostruka klackalica</translation>
    </message>
    <message>
        <source>triple-rocker</source>
        <translation>trostruka klackalica</translation>
    </message>
    <message>
        <source>change-point</source>
        <translation>prelazni</translation>
    </message>
    <message>
        <source>crank (input link) length</source>
        <translation>dužina poluge (ulaznog člana)</translation>
    </message>
    <message>
        <source>coupler length</source>
        <translation>dužina spojke</translation>
    </message>
    <message>
        <source>rocker (output link) length</source>
        <translation>dužina klackalice (izlaznog člana)</translation>
    </message>
    <message>
        <source>ground (frame) length</source>
        <translation>dužina postolja (nepokretnog člana)</translation>
    </message>
    <message>
        <source>crank angular velocity, constant (positive: α grows, counter-clockwise)</source>
        <translation>ugaona brzina poluge, konstantna (pozitivna: α raste, suprotno od kazaljke na satu)</translation>
    </message>
    <message>
        <source>coupler point M on BC: BM/BC (0 at B, 1 at C)</source>
        <translation>tačka M spojke na BC: BM/BC (0 u B, 1 u C)</translation>
    </message>
    <message>
        <source>assembly branch: +1 open (C left of B→D), −1 crossed</source>
        <translation>grana sklapanja: +1 otvorena (C levo od B→D), −1 ukrštena</translation>
    </message>
    <message>
        <source>branch = %1 is invalid: it must be +1 (open) or -1 (crossed).</source>
        <translation>branch = %1 nije dopuštena vrednost: mora biti +1 (otvorena) ili -1 (ukrštena).</translation>
    </message>
    <message>
        <source>The four-bar linkage has no parameter named &apos;%1&apos;.</source>
        <translation>Zglobni četvorougao nema parametar „%1“.</translation>
    </message>
    <message>
        <source>%1 = %2 is not shorter than %3 = %4: the links cannot close the loop ABCD for any crank angle α (each link must be shorter than the other three together).</source>
        <translation>%1 = %2 nije kraće od %3 = %4: članovi ne mogu da zatvore konturu ABCD ni za jedan ugao poluge α (svaki član mora biti kraći od zbira ostala tri).</translation>
    </message>
    <message>
        <source>at α = %1 the diagonal |BD| reaches BC + CD = %2: the coupler and the rocker are stretched in line (a dead point), and beyond it they cannot reach each other</source>
        <translation>pri α = %1 dijagonala |BD| dostiže BC + CD = %2: spojka i klackalica su opružene u liniju (mrtva tačka), a dalje ne mogu da se spoje</translation>
    </message>
    <message>
        <source>at α = %1 the diagonal |BD| falls to |BC − CD| = %2: the coupler and the rocker are folded in line (a dead point), and beyond it they cannot close the loop</source>
        <translation>pri α = %1 dijagonala |BD| pada na |BC − CD| = %2: spojka i klackalica su sklopljene u liniju (mrtva tačka), a dalje ne mogu da zatvore konturu</translation>
    </message>
    <message>
        <source>s + l = p + q (a change-point linkage): the links fold flat in line somewhere in the motion, where the open and crossed branches meet and a real linkage may switch branch.</source>
        <translation>s + l = p + q (prelazni mehanizam): u nekom položaju članovi se sklapaju u liniju; tu se susreću otvorena i ukrštena grana i stvarni mehanizam može da pređe na drugu granu.</translation>
    </message>
    <message>
        <source>The crank cannot turn fully: α is limited to [%1, %2], at whose ends the coupler and the rocker are in line (dead points where the crank cannot drive the rocker).</source>
        <translation>Poluga ne može da se okreće pun krug: α je ograničen na [%1, %2], a na krajevima tog intervala spojka i klackalica su u liniji (mrtve tačke u kojima poluga ne može da pokreće klackalicu).</translation>
    </message>
    <message>
        <source>The transmission angle falls to %1 at α = %2 (below %3°): the crank drives the rocker poorly there.</source>
        <translation>Ugao prenosa pada na %1 pri α = %2 (ispod %3°): tu poluga loše pokreće klackalicu.</translation>
    </message>
    <message>
        <source>crank angle at A, from AD counter-clockwise (actuated)</source>
        <translation>ugao poluge u A, od AD suprotno od kazaljke na satu (pogonjen)</translation>
    </message>
    <message>
        <source>rocker angle at D, from DA clockwise (output)</source>
        <translation>ugao klackalice u D, od DA u smeru kazaljke na satu (izlaz)</translation>
    </message>
    <message>
        <source>alpha must be a finite number.</source>
        <translation>Vrednost alpha mora biti konačan broj.</translation>
    </message>
    <message>
        <source>alpha = %1 is outside [0°, 360°]: the crank turns fully, give its angle within one turn.</source>
        <translation>alpha = %1 je van [0°, 360°]: poluga se okreće pun krug, zadajte njen ugao unutar jednog obrtaja.</translation>
    </message>
    <message>
        <source>alpha = %1 is outside the range of the crank of this %2 linkage, [%3, %4]: %5.</source>
        <translation>alpha = %1 je van opsega poluge ovog mehanizma (tip po Grashofu: %2), [%3, %4]: %5.</translation>
    </message>
    <message>
        <source>At alpha = %1 the crank joint B lies on D: the rocker&apos;s angle is undetermined.</source>
        <translation>Pri alpha = %1 zglob poluge B pada u D: ugao klackalice nije određen.</translation>
    </message>
    <message>
        <source>The loop ABCD does not close at alpha = %1.</source>
        <translation>Kontura ABCD se ne zatvara pri alpha = %1.</translation>
    </message>
    <message>
        <source>delta must be a finite number.</source>
        <translation>Vrednost delta mora biti konačan broj.</translation>
    </message>
    <message>
        <source>delta = %1 is outside the range the rocker reaches in the crossed branch, [%2, %3]: at its ends the crank and the coupler are in line, or the crank is at its own limit.</source>
        <translation>delta = %1 je van opsega koji klackalica dostiže u ukrštenoj grani, [%2, %3]: na njegovim krajevima poluga i spojka su u liniji ili je poluga na sopstvenoj granici.</translation>
    </message>
    <message>
        <source>delta = %1 is outside the range the rocker reaches in the open branch, [%2, %3]: at its ends the crank and the coupler are in line, or the crank is at its own limit.</source>
        <translation>delta = %1 je van opsega koji klackalica dostiže u otvorenoj grani, [%2, %3]: na njegovim krajevima poluga i spojka su u liniji ili je poluga na sopstvenoj granici.</translation>
    </message>
    <message>
        <source>At delta = %1 the rocker joint C lies on A: the crank angle is undetermined.</source>
        <translation>Pri delta = %1 zglob klackalice C pada u A: ugao poluge nije određen.</translation>
    </message>
    <message>
        <source>The crank cannot reach the coupler at delta = %1: |AC| = %2 is not between |AB − BC| and AB + BC.</source>
        <translation>Pri delta = %1 poluga ne može da dosegne spojku: |AC| = %2 nije između |AB − BC| i AB + BC.</translation>
    </message>
    <message>
        <source>The rocker reaches delta = %1 only in the other assembly branch; this design is crossed.</source>
        <translation>Klackalica dostiže delta = %1 samo u drugoj grani sklapanja; ova konstrukcija je sklopljena u ukrštenoj grani.</translation>
    </message>
    <message>
        <source>The rocker reaches delta = %1 only in the other assembly branch; this design is open.</source>
        <translation>Klackalica dostiže delta = %1 samo u drugoj grani sklapanja; ova konstrukcija je sklopljena u otvorenoj grani.</translation>
    </message>
    <message>
        <source>crank angle at A, from AD counter-clockwise</source>
        <translation>ugao poluge u A, od AD suprotno od kazaljke na satu</translation>
    </message>
    <message>
        <source>rocker angle at D, from DA clockwise</source>
        <translation>ugao klackalice u D, od DA u smeru kazaljke na satu</translation>
    </message>
    <message>
        <source>transmission angle at C, from CB to CD counter-clockwise (&lt; 0: crossed)</source>
        <translation>ugao prenosa u C, od CB ka CD suprotno od kazaljke na satu (&lt; 0: ukrštena grana)</translation>
    </message>
    <message>
        <source>angle at D from DA to DB (4)</source>
        <translation>ugao u D od DA ka DB (4)</translation>
    </message>
    <message>
        <source>angle at B from BA to BC, 360° − (α + γ + δ)</source>
        <translation>ugao u B od BA ka BC, 360° − (α + γ + δ)</translation>
    </message>
    <message>
        <source>J_q = ∂F/∂α = 2·AB·BC·sin β (0: inverse singularity)</source>
        <translation>J_q = ∂F/∂α = 2·AB·BC·sin β (0: singularitet inverzne kinematike)</translation>
    </message>
    <message>
        <source>J_x = −∂F/∂δ = −2·BC·CD·sin γ (0: direct singularity)</source>
        <translation>J_x = −∂F/∂δ = −2·BC·CD·sin γ (0: singularitet direktne kinematike)</translation>
    </message>
    <message>
        <source>α̇ = J·δ̇, J = J_q⁻¹·J_x = dα/dδ</source>
        <translation>α̇ = J·δ̇, J = J_q⁻¹·J_x = dα/dδ</translation>
    </message>
    <message>
        <source>transfer function dδ/dα = ω₃/ω₁ = −(9)</source>
        <translation>prenosna funkcija dδ/dα = ω₃/ω₁ = −(9)</translation>
    </message>
    <message>
        <source>crank angular velocity (constant)</source>
        <translation>ugaona brzina poluge (konstantna)</translation>
    </message>
    <message>
        <source>coupler angular velocity, counter-clockwise</source>
        <translation>ugaona brzina spojke, suprotno od kazaljke na satu</translation>
    </message>
    <message>
        <source>dδ/dt, exact (the document&apos;s (8) with the opposite sign)</source>
        <translation>dδ/dt, tačna vrednost (formula (8) iz rada sa suprotnim znakom)</translation>
    </message>
    <message>
        <source>coupler angular acceleration, counter-clockwise</source>
        <translation>ugaono ubrzanje spojke, suprotno od kazaljke na satu</translation>
    </message>
    <message>
        <source>d²δ/dt² at constant ω₁, exact (not the document&apos;s (14))</source>
        <translation>d²δ/dt² pri konstantnoj ω₁, tačna vrednost (ne formula (14) iz rada)</translation>
    </message>
    <message>
        <source>acute transmission angle min(|γ|, 180° − |γ|) (below 40°: poor)</source>
        <translation>oštar ugao prenosa min(|γ|, 180° − |γ|) (ispod 40°: loš prenos)</translation>
    </message>
    <message>
        <source>distance from the nearest singularity, min(|sin β|, |sin γ|)</source>
        <translation>udaljenost od najbližeg singulariteta, min(|sin β|, |sin γ|)</translation>
    </message>
    <message>
        <source>diagonal |BD|</source>
        <translation>dijagonala |BD|</translation>
    </message>
    <message>
        <source>coupler point M, x</source>
        <translation>tačka spojke M, x</translation>
    </message>
    <message>
        <source>coupler point M, y</source>
        <translation>tačka spojke M, y</translation>
    </message>
    <message>
        <source>instantaneous centre P of the coupler, x (none: AB ∥ DC)</source>
        <translation>trenutni pol brzina P spojke, x (nema: AB ∥ DC)</translation>
    </message>
    <message>
        <source>instantaneous centre P of the coupler, y (none: AB ∥ DC)</source>
        <translation>trenutni pol brzina P spojke, y (nema: AB ∥ DC)</translation>
    </message>
    <message>
        <source>assembly branch: open (C left of B→D) or crossed</source>
        <translation>grana sklapanja: otvorena (C levo od B→D) ili ukrštena</translation>
    </message>
    <message>
        <source>Grashof class from s + l against p + q</source>
        <translation>tip po Grashofu: s + l u poređenju sa p + q</translation>
    </message>
    <message>
        <source>crossed branch (same crank angle)</source>
        <translation>ukrštena grana (isti ugao poluge)</translation>
    </message>
    <message>
        <source>open branch (same crank angle)</source>
        <translation>otvorena grana (isti ugao poluge)</translation>
    </message>
    <message>
        <source>ground AD</source>
        <translation>postolje AD</translation>
    </message>
    <message>
        <source>coupler BC</source>
        <translation>spojka BC</translation>
    </message>
    <message>
        <source>rocker CD</source>
        <translation>klackalica CD</translation>
    </message>
    <message>
        <source>planar four-bar: ground AD, crank AB (driven at A), coupler BC, rocker CD</source>
        <translation>ravanski zglobni četvorougao: postolje AD, poluga AB (pogon u A), spojka BC, klackalica CD</translation>
    </message>
    <message>
        <source>BC (P at infinity: AB ∥ DC, the coupler translates)</source>
        <translation>BC (P u beskonačnosti: AB ∥ DC, spojka se kreće translatorno)</translation>
    </message>
    <message>
        <source>drag to turn the crank (sets α, direct kinematics)</source>
        <translation>prevucite da okrenete polugu (zadaje α, direktna kinematika)</translation>
    </message>
    <message>
        <source>drag to swing the rocker (sets δ, inverse kinematics)</source>
        <translation>prevucite da pomerite klackalicu (zadaje δ, inverzna kinematika)</translation>
    </message>
    <message>
        <source>coupler curve of M (crossed branch)</source>
        <translation>spojna kriva tačke M (ukrštena grana)</translation>
    </message>
    <message>
        <source>coupler curve of M (open branch)</source>
        <translation>spojna kriva tačke M (otvorena grana)</translation>
    </message>
    <message>
        <source>No joint variable with that index.</source>
        <translation>Ne postoji zglobna koordinata sa tim brojem.</translation>
    </message>
    <message>
        <source>not a number</source>
        <translation>nije broj</translation>
    </message>
    <message>
        <source>%1 (%2) = %3 is invalid: it must be greater than %4.</source>
        <translation>%1 (%2) = %3 nije dozvoljena vrednost: mora biti veće od %4.</translation>
    </message>
    <message>
        <source>%1 (%2) = %3 is invalid: it must be at least %4.</source>
        <translation>%1 (%2) = %3 nije dozvoljena vrednost: mora biti najmanje %4.</translation>
    </message>
    <message>
        <source>(%1, %2)</source>
        <translation>(%1; %2)</translation>
    </message>
    <message>
        <source>(%1, %2]</source>
        <translation>(%1; %2]</translation>
    </message>
    <message>
        <source>[%1, %2)</source>
        <translation>[%1; %2)</translation>
    </message>
    <message>
        <source>%1 (%2) = %3 is invalid: it must be %4.</source>
        <translation>%1 (%2) = %3 nije dozvoljena vrednost: mora biti u opsegu %4.</translation>
    </message>
    <message>
        <source>no kinematic chain is described for this mechanism</source>
        <translation>za ovaj mehanizam nije opisan kinematički lanac</translation>
    </message>
    <message>
        <source>pair &apos;%1&apos; does not join two different links of the chain</source>
        <translation>par „%1“ ne spaja dva različita člana lanca</translation>
    </message>
    <message>
        <source>pair &apos;%1&apos; has a point or an axis that is not finite</source>
        <translation>par „%1“ ima tačku ili osu koja nije konačna</translation>
    </message>
    <message>
        <source>pair &apos;%1&apos; has no axis</source>
        <translation>par „%1“ nema osu</translation>
    </message>
    <message>
        <source>the chain is marked planar (the plane z = 0) but pair &apos;%1&apos; is not</source>
        <translation>lanac je označen kao ravanski (ravan z = 0), ali par „%1“ nije</translation>
    </message>
    <message numerus="yes">
        <source>%n moving link(s)</source>
        <translation>
            <numerusform>%n pokretni član</numerusform>
            <numerusform>%n pokretna člana</numerusform>
            <numerusform>%n pokretnih članova</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n pair(s)</source>
        <translation>
            <numerusform>%n kinematički par</numerusform>
            <numerusform>%n kinematička para</numerusform>
            <numerusform>%n kinematičkih parova</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n loop(s)</source>
        <translation>
            <numerusform>%n zatvorena kontura</numerusform>
            <numerusform>%n zatvorene konture</numerusform>
            <numerusform>%n zatvorenih kontura</numerusform>
        </translation>
    </message>
    <message>
        <source>Planar chain of %1, %2 and %3: the rank of its constraint Jacobian gives mobility %4</source>
        <translation>Ravanski lanac (%1, %2 i %3): rang njegove Jakobijeve matrice veza daje pokretljivost %4</translation>
    </message>
    <message>
        <source>Spatial chain of %1, %2 and %3: the rank of its constraint Jacobian gives mobility %4</source>
        <translation>Prostorni lanac (%1, %2 i %3): rang njegove Jakobijeve matrice veza daje pokretljivost %4</translation>
    </message>
    <message numerus="yes">
        <source>Chebyshev&apos;s W = %1 is wrong: %n planar loop equation(s) is/are redundant (an overconstrained planar chain)</source>
        <translation>
            <numerusform>Čebiševljeva formula daje W = %1, što je pogrešno: %n jednačina ravnih kontura je suvišna (ravanski lanac sa suvišnim vezama)</numerusform>
            <numerusform>Čebiševljeva formula daje W = %1, što je pogrešno: %n jednačine ravnih kontura su suvišne (ravanski lanac sa suvišnim vezama)</numerusform>
            <numerusform>Čebiševljeva formula daje W = %1, što je pogrešno: %n jednačina ravnih kontura je suvišno (ravanski lanac sa suvišnim vezama)</numerusform>
        </translation>
    </message>
    <message>
        <source>Chebyshev&apos;s W = %1 is right</source>
        <translation>Čebiševljeva formula daje W = %1, što je tačno</translation>
    </message>
    <message>
        <source>Somov–Malyshev&apos;s W = %1 is right</source>
        <translation>formula Somova–Mališeva daje W = %1, što je tačno</translation>
    </message>
    <message>
        <source>(parallel axes: a planar loop imposes only 3)</source>
        <translation>(paralelne ose: ravanska kontura nameće samo 3)</translation>
    </message>
    <message>
        <source>(an overconstrained, &quot;paradoxical&quot; chain: it moves)</source>
        <translation>(„paradoksalan“ lanac sa suvišnim vezama: pokretan je)</translation>
    </message>
    <message>
        <source>(an overconstrained chain)</source>
        <translation>(lanac sa suvišnim vezama)</translation>
    </message>
    <message numerus="yes">
        <source>Somov–Malyshev&apos;s W = %1 is wrong: it counts 6 equations per loop and %n is/are redundant %2</source>
        <translation>
            <numerusform>formula Somova–Mališeva daje W = %1, što je pogrešno: ona računa 6 jednačina po konturi, a %n od njih je suvišna %2</numerusform>
            <numerusform>formula Somova–Mališeva daje W = %1, što je pogrešno: ona računa 6 jednačina po konturi, a %n od njih su suvišne %2</numerusform>
            <numerusform>formula Somova–Mališeva daje W = %1, što je pogrešno: ona računa 6 jednačina po konturi, a %n od njih je suvišno %2</numerusform>
        </translation>
    </message>
    <message>
        <source>at this pose the rank drops: the instantaneous mobility is %1, a singular pose</source>
        <translation>u ovom položaju rang opada: trenutna pokretljivost je %1, singularan položaj</translation>
    </message>
    <message>
        <source>no pair is actuated</source>
        <translation>nijedan par nije pogonjen</translation>
    </message>
    <message numerus="yes">
        <source>%n freedom(s)</source>
        <translation>
            <numerusform>%n stepen slobode</numerusform>
            <numerusform>%n stepena slobode</numerusform>
            <numerusform>%n stepeni slobode</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n actuated freedom(s) leave(s) %1 uncontrolled (under-actuated)</source>
        <translation>
            <numerusform>%n pogonjeni stepen slobode: bez upravljanja ostaje %1 (nedovoljno pogona)</numerusform>
            <numerusform>%n pogonjena stepena slobode: bez upravljanja ostaje %1 (nedovoljno pogona)</numerusform>
            <numerusform>%n pogonjenih stepeni slobode: bez upravljanja ostaje %1 (nedovoljno pogona)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n actuated freedom(s) for mobility %1: redundantly actuated</source>
        <translation>
            <numerusform>%n pogonjeni stepen slobode za pokretljivost %1: suvišan broj pogona</numerusform>
            <numerusform>%n pogonjena stepena slobode za pokretljivost %1: suvišan broj pogona</numerusform>
            <numerusform>%n pogonjenih stepeni slobode za pokretljivost %1: suvišan broj pogona</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n actuated freedom(s): fully actuated</source>
        <translation>
            <numerusform>%n pogonjeni stepen slobode: mehanizam je potpuno pogonjen</numerusform>
            <numerusform>%n pogonjena stepena slobode: mehanizam je potpuno pogonjen</numerusform>
            <numerusform>%n pogonjenih stepeni slobode: mehanizam je potpuno pogonjen</numerusform>
        </translation>
    </message>
    <message>
        <source>with the actuators locked it can still move instantaneously here (a direct singularity)</source>
        <translation>sa zakočenim pogonima lanac se ovde još može trenutno pomeriti (singularitet direktne kinematike)</translation>
    </message>
    <message numerus="yes">
        <source>%n idle freedom(s) is/are included</source>
        <translation>
            <numerusform>uključujući lokalne stepene slobode: %n</numerusform>
            <numerusform>uključujući lokalne stepene slobode: %n</numerusform>
            <numerusform>uključujući lokalne stepene slobode: %n</numerusform>
        </translation>
    </message>
    <message>
        <source>link %1</source>
        <translation>član %1</translation>
    </message>
    <message>
        <source>ground OB</source>
        <translation>postolje OB</translation>
    </message>
    <message>
        <source>crank OC</source>
        <translation>poluga OC</translation>
    </message>
    <message>
        <source>coupler CA</source>
        <translation>spojka CA</translation>
    </message>
    <message>
        <source>spatial parallelogram: four parallel revolute axes taken as a spatial chain</source>
        <translation>prostorni paralelogram: četiri paralelne ose obrtnih parova, posmatrane kao prostorni lanac</translation>
    </message>
    <message>
        <source>Bennett linkage: four revolute axes, opposite links equal, a/sin α = b/sin β</source>
        <translation>Benetov mehanizam: četiri ose obrtnih parova, naspramni članovi jednaki, a/sin α = b/sin β</translation>
    </message>
    <message>
        <source>spatial 4R loop with random axes (not a Bennett linkage)</source>
        <translation>prostorna kontura 4R sa slučajnim osama (nije Benetov mehanizam)</translation>
    </message>
    <message>
        <source>ground AE</source>
        <translation>postolje AE</translation>
    </message>
    <message>
        <source>link DC</source>
        <translation>spojka DC</translation>
    </message>
    <message>
        <source>crank ED</source>
        <translation>poluga ED</translation>
    </message>
    <message>
        <source>planar five-bar: ground, two driven cranks, two distal links</source>
        <translation>ravanski petočlani mehanizam: postolje, dve pogonjene poluge, dve spojke</translation>
    </message>
    <message>
        <source>Cannot analyse the mobility: %1.</source>
        <translation>Pokretljivost ne može da se odredi: %1.</translation>
    </message>
    <message>
        <source>crank BA</source>
        <translation>poluga BA</translation>
    </message>
    <message>
        <source>%1 (back)</source>
        <translation>%1 (pozadi)</translation>
    </message>
    <message>
        <source>%1 (front)</source>
        <translation>%1 (napred)</translation>
    </message>
    <message>
        <source>base</source>
        <translation>osnova</translation>
    </message>
    <message>
        <source>clevis</source>
        <translation>viljuška</translation>
    </message>
    <message>
        <source>stepper motor</source>
        <translation>koračni motor</translation>
    </message>
    <message>
        <source>lead screw</source>
        <translation>zavojno vreteno</translation>
    </message>
    <message>
        <source>rod end</source>
        <translation>zglobni završetak vretena</translation>
    </message>
    <message>
        <source>guide %1</source>
        <translation>vođica %1</translation>
    </message>
    <message>
        <source>end stop</source>
        <translation>graničnik</translation>
    </message>
    <message>
        <source>carriage %1</source>
        <translation>kolica %1</translation>
    </message>
    <message>
        <source>platform</source>
        <translation>platforma</translation>
    </message>
    <message>
        <source>guide 1 reference point, x</source>
        <translation>referentna tačka vođice 1, x</translation>
    </message>
    <message>
        <source>guide 1 reference point, y</source>
        <translation>referentna tačka vođice 1, y</translation>
    </message>
    <message>
        <source>guide 2 reference point, x</source>
        <translation>referentna tačka vođice 2, x</translation>
    </message>
    <message>
        <source>guide 2 reference point, y</source>
        <translation>referentna tačka vođice 2, y</translation>
    </message>
    <message>
        <source>direction of guide 1</source>
        <translation>orijentacija vođice 1</translation>
    </message>
    <message>
        <source>direction of guide 2</source>
        <translation>orijentacija vođice 2</translation>
    </message>
    <message>
        <source>turn of guide 1 from the vertical (α₁ = 270° + γ₁)</source>
        <translation>zaokret vođice 1 od vertikale (α₁ = 270° + γ₁)</translation>
    </message>
    <message>
        <source>turn of guide 2 from the vertical (α₂ = 270° + γ₂)</source>
        <translation>zaokret vođice 2 od vertikale (α₂ = 270° + γ₂)</translation>
    </message>
    <message>
        <source>length of link S₁</source>
        <translation>dužina spojke S₁</translation>
    </message>
    <message>
        <source>length of link S₂</source>
        <translation>dužina spojke S₂</translation>
    </message>
    <message>
        <source>start of the stroke</source>
        <translation>početak hoda</translation>
    </message>
    <message>
        <source>end of the stroke</source>
        <translation>kraj hoda</translation>
    </message>
    <message>
        <source>working mode of leg 1: sign in p₁ = B₁ ± √…</source>
        <translation>radni režim noge 1: znak u p₁ = B₁ ± √…</translation>
    </message>
    <message>
        <source>working mode of leg 2: sign in p₂ = B₂ ± √…</source>
        <translation>radni režim noge 2: znak u p₂ = B₂ ± √…</translation>
    </message>
    <message>
        <source>assembly mode: +1 platform left of Z₁→Z₂</source>
        <translation>način sklapanja: +1 platforma levo od Z₁→Z₂</translation>
    </message>
    <message>
        <source>links kept on the inner side of the guides (1: on)</source>
        <translation>spojke samo sa unutrašnje strane vođica (1: uključeno)</translation>
    </message>
    <message>
        <source>drawn width of a guide</source>
        <translation>širina vođice na crtežu</translation>
    </message>
    <message>
        <source>MOMA has no parameter named &apos;%1&apos;.</source>
        <translation>MOMA nema parametar „%1“.</translation>
    </message>
    <message>
        <source>%1 and %2 both turn guide %3: give one of them.</source>
        <translation>%1 i %2 oba zakreću vođicu %3: zadajte samo jedan od njih.</translation>
    </message>
    <message>
        <source>%1 = %2 is invalid: it must be -1 or +1.</source>
        <translation>%1 = %2 nije dozvoljena vrednost: mora biti -1 ili +1.</translation>
    </message>
    <message>
        <source>one_side = %1 is invalid: it must be 0 (off) or 1 (on).</source>
        <translation>one_side = %1 nije dozvoljena vrednost: mora biti 0 (isključeno) ili 1 (uključeno).</translation>
    </message>
    <message>
        <source>p_min = %1 mm must be less than p_max = %2 mm.</source>
        <translation>p_min = %1 mm mora biti manje od p_max = %2 mm.</translation>
    </message>
    <message>
        <source>The guides lie on one line and their strokes overlap: the slider joints Z₁ and Z₂ could coincide. Move R₂ or turn a guide.</source>
        <translation>Vođice leže na istoj pravoj i hodovi im se preklapaju: zglobovi klizača Z₁ i Z₂ mogu da se poklope. Pomerite R₂ ili zaokrenite vođicu.</translation>
    </message>
    <message>
        <source>This configuration has no workspace: with l₁ = %1 mm, l₂ = %2 mm and strokes [%3, %4] mm the links cannot meet in the chosen working and assembly modes.</source>
        <translation>Ova konfiguracija nema radni prostor: sa l₁ = %1 mm, l₂ = %2 mm i hodom [%3; %4] mm spojke ne mogu da se spoje u izabranim radnim režimima i načinu sklapanja.</translation>
    </message>
    <message>
        <source>The guides cross inside their strokes: the sliders can collide there.</source>
        <translation>Vođice se seku unutar hoda: tu klizači mogu da se sudare.</translation>
    </message>
    <message>
        <source>slider 1 position (actuated)</source>
        <translation>položaj klizača 1 (pogonska koordinata)</translation>
    </message>
    <message>
        <source>slider 2 position (actuated)</source>
        <translation>položaj klizača 2 (pogonska koordinata)</translation>
    </message>
    <message>
        <source>platform x</source>
        <translation>platforma, x</translation>
    </message>
    <message>
        <source>platform y</source>
        <translation>platforma, y</translation>
    </message>
    <message>
        <source>link S%1 would lie on the outer side of guide %2 (the one-side constraint is on)</source>
        <translation>spojka S%1 bi se našla sa spoljašnje strane vođice %2 (uključeno je ograničenje na jednu stranu)</translation>
    </message>
    <message>
        <source>The slider joints Z₁ and Z₂ coincide at p₁ = %1 mm, p₂ = %2 mm: the platform position is undetermined.</source>
        <translation>Zglobovi klizača Z₁ i Z₂ se poklapaju pri p₁ = %1 mm, p₂ = %2 mm: položaj platforme nije određen.</translation>
    </message>
    <message>
        <source>The links cannot meet at p₁ = %1 mm, p₂ = %2 mm: |Z₁Z₂| = %3 mm is more than l₁ + l₂ = %4 mm.</source>
        <translation>Spojke ne mogu da se spoje pri p₁ = %1 mm, p₂ = %2 mm: |Z₁Z₂| = %3 mm je veće od l₁ + l₂ = %4 mm.</translation>
    </message>
    <message>
        <source>The links cannot meet at p₁ = %1 mm, p₂ = %2 mm: |Z₁Z₂| = %3 mm is less than |l₁ − l₂| = %4 mm.</source>
        <translation>Spojke ne mogu da se spoje pri p₁ = %1 mm, p₂ = %2 mm: |Z₁Z₂| = %3 mm je manje od |l₁ − l₂| = %4 mm.</translation>
    </message>
    <message>
        <source>At p₁ = %1 mm, p₂ = %2 mm leg %3 would be past perpendicular to its guide, in its other working mode (an inverse singularity lies between); switch the mode to go on.</source>
        <translation>Pri p₁ = %1 mm, p₂ = %2 mm noga %3 bi prešla preko položaja upravnog na svoju vođicu, u drugi radni režim (između je singularitet inverzne kinematike); promenite režim da biste nastavili.</translation>
    </message>
    <message>
        <source>At p₁ = %1 mm, p₂ = %2 mm %3.</source>
        <translation>Pri p₁ = %1 mm, p₂ = %2 mm %3.</translation>
    </message>
    <message>
        <source>The platform cannot reach %1: it lies more than l%2 = %3 mm from guide %4.</source>
        <translation>Platforma ne može da stigne do tačke %1: tačka je od vođice %4 udaljena više od l%2 = %3 mm.</translation>
    </message>
    <message>
        <source>The platform cannot reach %1: slider %2 would have to be at p%3 = %4 mm, outside its stroke [%5, %6] mm.</source>
        <translation>Platforma ne može da stigne do tačke %1: klizač %2 bi morao da bude na p%3 = %4 mm, van svog hoda [%5; %6] mm.</translation>
    </message>
    <message>
        <source>The platform cannot reach %1 in this assembly mode: it would cross the line Z₁Z₂, where the links are collinear (a direct singularity); switch the assembly mode to go on.</source>
        <translation>Platforma ne može da stigne do tačke %1 u ovom načinu sklapanja: prešla bi pravu Z₁Z₂, na kojoj su spojke kolinearne (singularitet direktne kinematike); promenite način sklapanja da biste nastavili.</translation>
    </message>
    <message>
        <source>The platform cannot reach %1: %2.</source>
        <translation>Platforma ne može da stigne do tačke %1: %2.</translation>
    </message>
    <message>
        <source>%1 = %2 mm is outside the stroke [%3, %4] mm.</source>
        <translation>%1 = %2 mm je van hoda [%3; %4] mm.</translation>
    </message>
    <message>
        <source>slider 1 position</source>
        <translation>položaj klizača 1</translation>
    </message>
    <message>
        <source>slider 2 position</source>
        <translation>položaj klizača 2</translation>
    </message>
    <message>
        <source>J_x rows 2(P − Z_i) (20)</source>
        <translation>vrste J_x: 2(P − Z_i) (20)</translation>
    </message>
    <message>
        <source>ṗ = J·Ṗ, J = −J_p⁻¹·J_x ((21) up to its sign)</source>
        <translation>ṗ = J·Ṗ, J = −J_p⁻¹·J_x ((21) do na znak)</translation>
    </message>
    <message>
        <source>0 at an inverse singularity</source>
        <translation>0 u singularitetu inverzne kinematike</translation>
    </message>
    <message>
        <source>0 at a direct singularity</source>
        <translation>0 u singularitetu direktne kinematike</translation>
    </message>
    <message>
        <source>angle between link S₁ and guide 1 (90°: inverse singularity)</source>
        <translation>ugao između spojke S₁ i vođice 1 (90°: singularitet inverzne kinematike)</translation>
    </message>
    <message>
        <source>angle between link S₂ and guide 2 (90°: inverse singularity)</source>
        <translation>ugao između spojke S₂ i vođice 2 (90°: singularitet inverzne kinematike)</translation>
    </message>
    <message>
        <source>angle between the links (0°, 180°: direct singularity)</source>
        <translation>ugao između spojki (0°, 180°: singularitet direktne kinematike)</translation>
    </message>
    <message>
        <source>other assembly mode (same slider positions)</source>
        <translation>drugi način sklapanja (isti položaji klizača)</translation>
    </message>
    <message>
        <source>leg 1: other working mode (same platform position)</source>
        <translation>noga 1: drugi radni režim (isti položaj platforme)</translation>
    </message>
    <message>
        <source>leg 2: other working mode (same platform position)</source>
        <translation>noga 2: drugi radni režim (isti položaj platforme)</translation>
    </message>
    <message>
        <source>slider K₁</source>
        <translation>klizač K₁</translation>
    </message>
    <message>
        <source>slider K₂</source>
        <translation>klizač K₂</translation>
    </message>
    <message>
        <source>link S₁</source>
        <translation>spojka S₁</translation>
    </message>
    <message>
        <source>link S₂</source>
        <translation>spojka S₂</translation>
    </message>
    <message>
        <source>guide PO₁</source>
        <translation>vođica PO₁</translation>
    </message>
    <message>
        <source>guide PO₂</source>
        <translation>vođica PO₂</translation>
    </message>
    <message>
        <source>MOMA: two sliders on powered guides, two links meeting at the platform joint P</source>
        <translation>MOMA: dva klizača na pogonskim vođicama i dve spojke spojene u zglobu platforme P</translation>
    </message>
    <message>
        <source>drag to move the platform (inverse kinematics)</source>
        <translation>prevucite da biste pomerili platformu (inverzna kinematika)</translation>
    </message>
    <message>
        <source>drag along guide 1 to set p₁ (direct kinematics)</source>
        <translation>prevucite duž vođice 1 da biste zadali p₁ (direktna kinematika)</translation>
    </message>
    <message>
        <source>drag along guide 2 to set p₂ (direct kinematics)</source>
        <translation>prevucite duž vođice 2 da biste zadali p₂ (direktna kinematika)</translation>
    </message>
    <message>
        <source>link ⟂ guide</source>
        <translation>spojka ⟂ vođici</translation>
    </message>
    <message>
        <source>links collinear</source>
        <translation>spojke kolinearne</translation>
    </message>
    <message>
        <source>link 1 ⟂ guide 1</source>
        <translation>spojka 1 ⟂ vođici 1</translation>
    </message>
    <message>
        <source>link 2 ⟂ guide 2</source>
        <translation>spojka 2 ⟂ vođici 2</translation>
    </message>
    <message>
        <source>crossed (X)</source>
        <translation>ukršteni (X)</translation>
    </message>
    <message>
        <source>extended (O)</source>
        <translation>opruženi (O)</translation>
    </message>
    <message>
        <source>rod length</source>
        <translation>dužina štapa</translation>
    </message>
    <message>
        <source>platform width</source>
        <translation>širina platforme</translation>
    </message>
    <message>
        <source>transverse guide length (slider positions 0…L)</source>
        <translation>dužina poprečnih vođica (položaji klizača 0…L)</translation>
    </message>
    <message>
        <source>spacing of the transverse guides</source>
        <translation>razmak poprečnih vođica</translation>
    </message>
    <message>
        <source>start of the longitudinal travel</source>
        <translation>početak uzdužnog hoda</translation>
    </message>
    <message>
        <source>end of the longitudinal travel</source>
        <translation>kraj uzdužnog hoda</translation>
    </message>
    <message>
        <source>+1 extended (O), −1 crossed (X)</source>
        <translation>+1 opruženi (O), −1 ukršteni (X)</translation>
    </message>
    <message>
        <source>The O-X glide has no parameter named &apos;%1&apos;.</source>
        <translation>Mehanizam O-X glide nema parametar „%1”.</translation>
    </message>
    <message>
        <source>mode = %1 is invalid: it must be +1 (O, extended) or -1 (X, crossed).</source>
        <translation>mode = %1 nije dozvoljena vrednost: mora biti +1 (O, opruženi oblik) ili -1 (X, ukršteni).</translation>
    </message>
    <message>
        <source>mode must be +1 (O, extended) or -1 (X, crossed).</source>
        <translation>mode mora biti +1 (O, opruženi oblik) ili -1 (X, ukršteni).</translation>
    </message>
    <message>
        <source>s = %1 must be less than 2l = %2: a platform that wide keeps the rods from ever crossing, so there is no X form.</source>
        <translation>s = %1 mora biti manje od 2l = %2: sa tako širokom platformom štapovi se nikada ne ukrštaju, pa ukršteni (X) oblik ne postoji.</translation>
    </message>
    <message>
        <source>L = %1 must be more than the platform width s = %2: with guides that short the extended (O) form has no workspace.</source>
        <translation>L = %1 mora biti veće od širine platforme s = %2: sa tako kratkim vođicama opruženi (O) oblik nema radni prostor.</translation>
    </message>
    <message>
        <source>z_min = %1 must be less than z_max = %2.</source>
        <translation>z_min = %1 mora biti manje od z_max = %2.</translation>
    </message>
    <message>
        <source>The crossed (X) form has no workspace with L = %1, s = %2 and l = %3.</source>
        <translation>Ukršteni (X) oblik nema radni prostor za L = %1, s = %2 i l = %3.</translation>
    </message>
    <message>
        <source>The extended (O) form has no workspace with L = %1, s = %2 and l = %3.</source>
        <translation>Opruženi (O) oblik nema radni prostor za L = %1, s = %2 i l = %3.</translation>
    </message>
    <message>
        <source>slider pair AB position (actuated)</source>
        <translation>položaj para klizača AB (pogonski)</translation>
    </message>
    <message>
        <source>slider pair CD position (actuated)</source>
        <translation>položaj para klizača CD (pogonski)</translation>
    </message>
    <message>
        <source>longitudinal position (actuated serial axis)</source>
        <translation>uzdužni položaj (pogonska serijska osa)</translation>
    </message>
    <message>
        <source>platform centre T, x</source>
        <translation>centar platforme T, x</translation>
    </message>
    <message>
        <source>platform centre T, y</source>
        <translation>centar platforme T, y</translation>
    </message>
    <message>
        <source>The platform cannot reach %1: y is more than the rod length l = %2.</source>
        <translation>Platforma ne može da dostigne %1: y je veće od dužine štapa l = %2.</translation>
    </message>
    <message>
        <source>The platform cannot reach %1: it would pass the rod joints&apos; plane y = 0, where the rods lie along the guides (a direct singularity).</source>
        <translation>Platforma ne može da dostigne %1: prešla bi ravan zglobova štapova y = 0, gde štapovi leže duž vođica (singularitet direktne kinematike).</translation>
    </message>
    <message>
        <source>The crossed (X) form cannot reach %1: slider pair %2 would have to be at %3 = %4, off its guides (0…%5 mm).</source>
        <translation>Ukršteni (X) oblik ne može da dostigne %1: par klizača %2 morao bi da bude na %3 = %4, van svojih vođica (0…%5 mm).</translation>
    </message>
    <message>
        <source>The extended (O) form cannot reach %1: slider pair %2 would have to be at %3 = %4, off its guides (0…%5 mm).</source>
        <translation>Opruženi (O) oblik ne može da dostigne %1: par klizača %2 morao bi da bude na %3 = %4, van svojih vođica (0…%5 mm).</translation>
    </message>
    <message>
        <source>%1 = %2 is off the guides (%3…%4 mm).</source>
        <translation>%1 = %2 je van vođica (%3…%4 mm).</translation>
    </message>
    <message>
        <source>%1 = %2 is outside the travel (%3…%4 mm).</source>
        <translation>%1 = %2 je van hoda (%3…%4 mm).</translation>
    </message>
    <message>
        <source>The rods cannot reach the platform at x_AB = %1, x_CD = %2: |x_CD − x_AB − s| = %3 is more than 2l = %4.</source>
        <translation>Štapovi ne mogu da dosegnu platformu za x_AB = %1, x_CD = %2: |x_CD − x_AB − s| = %3 je veće od 2l = %4.</translation>
    </message>
    <message>
        <source>x_CD − x_AB = %1 is less than s = %2: these slider positions hold the crossed (X) form, and the mechanism is extended (O). At x_CD − x_AB = s the rods are parallel and the platform can swing (a singularity), so the pairs do not pass it on their own: switch the form to go on.</source>
        <translation>x_CD − x_AB = %1 je manje od s = %2: ovi položaji klizača odgovaraju ukrštenom (X) obliku, a mehanizam je u opruženom (O). Za x_CD − x_AB = s štapovi su paralelni i platforma može da se njiše (singularitet), pa ga parovi klizača sami ne prelaze: promenite oblik da biste nastavili.</translation>
    </message>
    <message>
        <source>x_CD − x_AB = %1 is more than s = %2: these slider positions hold the extended (O) form, and the mechanism is crossed (X). At x_CD − x_AB = s the rods are parallel and the platform can swing (a singularity), so the pairs do not pass it on their own: switch the form to go on.</source>
        <translation>x_CD − x_AB = %1 je veće od s = %2: ovi položaji klizača odgovaraju opruženom (O) obliku, a mehanizam je u ukrštenom (X). Za x_CD − x_AB = s štapovi su paralelni i platforma može da se njiše (singularitet), pa ga parovi klizača sami ne prelaze: promenite oblik da biste nastavili.</translation>
    </message>
    <message>
        <source>slider pair AB position</source>
        <translation>položaj para klizača AB</translation>
    </message>
    <message>
        <source>slider pair CD position</source>
        <translation>položaj para klizača CD</translation>
    </message>
    <message>
        <source>longitudinal position</source>
        <translation>uzdužni položaj</translation>
    </message>
    <message>
        <source>J_q = diag(−2u₁, −2u₂), u_i the rods&apos; runs along the guides</source>
        <translation>J_q = diag(−2u₁, −2u₂), u_i — projekcije štapova na vođice</translation>
    </message>
    <message>
        <source>J_x rows (2u_i, 2y)</source>
        <translation>vrste J_x: (2u_i, 2y)</translation>
    </message>
    <message>
        <source>q̇ = J·ẋ of the planar part, J = −J_q⁻¹·J_x</source>
        <translation>q̇ = J·ẋ ravanskog dela, J = −J_q⁻¹·J_x</translation>
    </message>
    <message>
        <source>angle between the rods and the guides (90°: the O↔X crossing)</source>
        <translation>ugao između štapova i vođica (90°: prelaz O↔X)</translation>
    </message>
    <message>
        <source>distance from the O↔X crossing (0 there; &gt; 0 O, &lt; 0 X)</source>
        <translation>rastojanje od prelaza O↔X (0 na njemu; &gt; 0 O, &lt; 0 X)</translation>
    </message>
    <message>
        <source>form of the pose: O extended, X crossed</source>
        <translation>oblik položaja: O opruženi, X ukršteni</translation>
    </message>
    <message>
        <source>crossed (X) form (same platform position)</source>
        <translation>ukršteni (X) oblik (isti položaj platforme)</translation>
    </message>
    <message>
        <source>extended (O) form (same platform position)</source>
        <translation>opruženi (O) oblik (isti položaj platforme)</translation>
    </message>
    <message>
        <source>rods ⟂ guides: the O↔X crossing</source>
        <translation>štapovi ⟂ vođicama: prelaz O↔X</translation>
    </message>
    <message>
        <source>rods parallel: the platform can swing</source>
        <translation>štapovi paralelni: platforma može da se njiše</translation>
    </message>
    <message>
        <source>rods along the guides</source>
        <translation>štapovi duž vođica</translation>
    </message>
    <message>
        <source>rods ⟂ guides</source>
        <translation>štapovi ⟂ vođicama</translation>
    </message>
    <message>
        <source>drag to move the platform (inverse kinematics, in the current form)</source>
        <translation>prevucite da biste pomerili platformu (inverzna kinematika, u trenutnom obliku)</translation>
    </message>
    <message>
        <source>drag along the guides to set x_AB (direct kinematics)</source>
        <translation>prevucite duž vođica da biste zadali x_AB (direktna kinematika)</translation>
    </message>
    <message>
        <source>drag along the guides to set x_CD (direct kinematics)</source>
        <translation>prevucite duž vođica da biste zadali x_CD (direktna kinematika)</translation>
    </message>
    <message>
        <source>longitudinal carriage</source>
        <translation>uzdužna kolica</translation>
    </message>
    <message>
        <source>end plate</source>
        <translation>čeona ploča</translation>
    </message>
    <message>
        <source>longitudinal guide</source>
        <translation>uzdužna vođica</translation>
    </message>
    <message>
        <source>slider %1</source>
        <translation>klizač %1</translation>
    </message>
    <message>
        <source>compensation element %1</source>
        <translation>kompenzacioni element %1</translation>
    </message>
    <message>
        <source>rod joint %1</source>
        <translation>zglob štapa %1</translation>
    </message>
    <message>
        <source>pair AB</source>
        <translation>par AB</translation>
    </message>
    <message>
        <source>pair CD</source>
        <translation>par CD</translation>
    </message>
    <message>
        <source>rod %1</source>
        <translation>štap %1</translation>
    </message>
    <message>
        <source>spherical joint %1</source>
        <translation>sferni zglob %1</translation>
    </message>
    <message>
        <source>carriage</source>
        <translation>kolica</translation>
    </message>
    <message>
        <source>slider pair AB</source>
        <translation>par klizača AB</translation>
    </message>
    <message>
        <source>slider pair CD</source>
        <translation>par klizača CD</translation>
    </message>
    <message>
        <source>O-X glide: carriage on the longitudinal guides, slider pairs AB and CD, four rods (revolute at the sliders, spherical at the platform), platform</source>
        <translation>O-X glide: kolica na uzdužnim vođicama, parovi klizača AB i CD, četiri štapa (obrtni zglobovi na klizačima, sferni na platformi), platforma</translation>
    </message>
    <message>
        <source>crank (lever) length</source>
        <translation>dužina poluge</translation>
    </message>
    <message>
        <source>base and coupler length</source>
        <translation>dužina osnove i spojke</translation>
    </message>
    <message>
        <source>ratio k = b/a</source>
        <translation>odnos k = b/a</translation>
    </message>
    <message>
        <source>lower limit of θ</source>
        <translation>donja granica θ</translation>
    </message>
    <message>
        <source>upper limit of θ</source>
        <translation>gornja granica θ</translation>
    </message>
    <message>
        <source>lead of the screw</source>
        <translation>korak zavojnog vretena</translation>
    </message>
    <message>
        <source>linear step</source>
        <translation>linearni korak</translation>
    </message>
    <message>
        <source>max. linear speed</source>
        <translation>maks. linearna brzina</translation>
    </message>
    <message>
        <source>max. thrust force</source>
        <translation>maks. pogonska sila</translation>
    </message>
    <message>
        <source>screw efficiency</source>
        <translation>stepen iskorišćenja zavojnog vretena</translation>
    </message>
    <message>
        <source>motor body length</source>
        <translation>dužina kućišta motora</translation>
    </message>
    <message>
        <source>motor body width</source>
        <translation>širina kućišta motora</translation>
    </message>
    <message>
        <source>screw diameter</source>
        <translation>prečnik zavojnog vretena</translation>
    </message>
    <message>
        <source>k = b/a = %1 is out of proportion: it must lie between 1e-6 and 1e6.</source>
        <translation>k = b/a = %1 je van svake mere: mora biti između 1e-6 i 1e6.</translation>
    </message>
    <message>
        <source>theta_min = %1° must be less than theta_max = %2°.</source>
        <translation>theta_min = %1° mora biti manje od theta_max = %2°.</translation>
    </message>
    <message>
        <source>k = %1 and b = %2 mm both set the coupler: give b or k, not both.</source>
        <translation>k = %1 i b = %2 mm oba određuju spojku: zadajte b ili k, ne oba.</translation>
    </message>
    <message>
        <source>The П-joint has no parameter named &apos;%1&apos;.</source>
        <translation>P-zglob nema parametar „%1”.</translation>
    </message>
    <message>
        <source>theta_max = %1° must be greater than theta_min = %2°.</source>
        <translation>theta_max = %1° mora biti veće od theta_min = %2°.</translation>
    </message>
    <message>
        <source>The motor body (%1 mm) is longer than d_min = %2 mm: the diagonal cannot retract that far.</source>
        <translation>Kućište motora (%1 mm) duže je od d_min = %2 mm: dijagonala ne može toliko da se skrati.</translation>
    </message>
    <message>
        <source>diagonal length (actuated)</source>
        <translation>dužina dijagonale (pogonska)</translation>
    </message>
    <message>
        <source>output angle</source>
        <translation>izlazni ugao</translation>
    </message>
    <message>
        <source>d = %1 mm is outside the stroke [%2, %3] mm that the θ range allows.</source>
        <translation>d = %1 mm je van hoda [%2; %3] mm koji dopušta opseg θ.</translation>
    </message>
    <message>
        <source>θ = %1° is outside the design range [%2, %3]°.</source>
        <translation>θ = %1° je van projektovanog opsega [%2; %3]°.</translation>
    </message>
    <message>
        <source>diagonal length</source>
        <translation>dužina dijagonale</translation>
    </message>
    <message>
        <source>passive angle of the diagonal</source>
        <translation>pasivni ugao dijagonale</translation>
    </message>
    <message>
        <source>transmission angle</source>
        <translation>ugao prenosa</translation>
    </message>
    <message>
        <source>Jacobian ḋ = J·θ̇</source>
        <translation>Jakobijan ḋ = J·θ̇</translation>
    </message>
    <message>
        <source>inverse Jacobian θ̇ = J⁻¹·ḋ</source>
        <translation>inverzni jakobijan θ̇ = J⁻¹·ḋ</translation>
    </message>
    <message>
        <source>J_d = 2d</source>
        <translation>J_d = 2d</translation>
    </message>
    <message>
        <source>J_θ = 2a²k·cos θ</source>
        <translation>J_θ = 2a²k·cos θ</translation>
    </message>
    <message>
        <source>derivative of J</source>
        <translation>izvod J</translation>
    </message>
    <message>
        <source>output torque at F_max</source>
        <translation>izlazni moment pri F_max</translation>
    </message>
    <message>
        <source>output speed θ̇ at ḋ_max</source>
        <translation>izlazna ugaona brzina θ̇ pri ḋ_max</translation>
    </message>
    <message>
        <source>output resolution per step</source>
        <translation>izlazna rezolucija po koraku</translation>
    </message>
    <message>
        <source>motor torque at F_max</source>
        <translation>moment motora pri F_max</translation>
    </message>
    <message>
        <source>diagonal at θ_min</source>
        <translation>dijagonala pri θ_min</translation>
    </message>
    <message>
        <source>diagonal at θ_max</source>
        <translation>dijagonala pri θ_max</translation>
    </message>
    <message>
        <source>actuator stroke</source>
        <translation>hod aktuatora</translation>
    </message>
    <message>
        <source>recommended range from (J ≥ 60 % of best)</source>
        <translation>preporučeni opseg: od (J ≥ 60 % najvećeg)</translation>
    </message>
    <message>
        <source>recommended range to (J ≥ 60 % of best)</source>
        <translation>preporučeni opseg: do (J ≥ 60 % najvećeg)</translation>
    </message>
    <message>
        <source>motor body</source>
        <translation>kućište motora</translation>
    </message>
    <message>
        <source>screw</source>
        <translation>vreteno</translation>
    </message>
    <message>
        <source>O (motor)</source>
        <translation>O (motor)</translation>
    </message>
    <message>
        <source>A (screw)</source>
        <translation>A (vreteno)</translation>
    </message>
    <message>
        <source>active П-joint: hinged parallelogram OBAC with the telescopic diagonal OA (motor body and screw)</source>
        <translation>aktivni P-zglob: zglobni paralelogram OBAC sa teleskopskom dijagonalom OA (kućište motora i vreteno)</translation>
    </message>
    <message>
        <source>drag A to set θ</source>
        <translation>prevucite A da biste zadali θ</translation>
    </message>
    <message>
        <source>drag C to set θ</source>
        <translation>prevucite C da biste zadali θ</translation>
    </message>
    <message>
        <source>The pointer is on the pivot: θ is undefined there.</source>
        <translation>Pokazivač je na osi obrtanja: tu ugao θ nije određen.</translation>
    </message>
    <message>
        <source>Active П-joint</source>
        <translation>Aktivni P-zglob</translation>
    </message>
    <message>
        <source>MOMA 2-axis parallel mechanism</source>
        <translation>Dvoosni paralelni mehanizam MOMA</translation>
    </message>
    <message>
        <source>O-X glide hybrid mechanism</source>
        <translation>Hibridni mehanizam O-X glide</translation>
    </message>
    <message>
        <source>Planar four-bar linkage</source>
        <translation>Ravanski zglobni četvorougao</translation>
    </message>
    <message>
        <source>Planar five-bar linkage</source>
        <translation>Ravanski zglobni petočlani mehanizam</translation>
    </message>
    <message>
        <source>Unknown mechanism kind &apos;%1&apos;.</source>
        <translation>Nepoznat tip mehanizma „%1”.</translation>
    </message>
    <message>
        <source>A %1 has no parameter named &apos;%2&apos;.</source>
        <translation>Mehanizam „%1” nema parametar „%2”.</translation>
    </message>
    <message>
        <source>link</source>
        <translation>član</translation>
    </message>
    <message>
        <source>motor</source>
        <translation>motor</translation>
    </message>
    <message>
        <source>motor %1</source>
        <translation>motor %1</translation>
    </message>
    <message>
        <source>screw %1</source>
        <translation>vreteno %1</translation>
    </message>
    <message>
        <source>guide</source>
        <translation>vođica</translation>
    </message>
    <message>
        <source>end stop %1</source>
        <translation>graničnik %1</translation>
    </message>
    <message>
        <source>slider</source>
        <translation>klizač</translation>
    </message>
    <message>
        <source>support</source>
        <translation>oslonac</translation>
    </message>
    <message>
        <source>support %1</source>
        <translation>oslonac %1</translation>
    </message>
    <message>
        <source>point</source>
        <translation>tačka</translation>
    </message>
    <message>
        <source>point %1</source>
        <translation>tačka %1</translation>
    </message>
    <message>
        <source>joint</source>
        <translation>zglob</translation>
    </message>
    <message>
        <source>joint %1</source>
        <translation>zglob %1</translation>
    </message>
    <message>
        <source>one side</source>
        <translation>jedna strana</translation>
    </message>
    <message>
        <source>form</source>
        <translation>oblik</translation>
    </message>
    <message>
        <source>input of leg 1</source>
        <translation>ulaz noge 1</translation>
    </message>
    <message>
        <source>input of leg 2</source>
        <translation>ulaz noge 2</translation>
    </message>
    <message>
        <source>input of leg 3</source>
        <translation>ulaz noge 3</translation>
    </message>
    <message>
        <source>platform angle</source>
        <translation>ugao platforme</translation>
    </message>
    <message>
        <source>J_q = diag(∂g_i/∂q_i)</source>
        <translation>J_q = diag(∂g_i/∂q_i)</translation>
    </message>
    <message>
        <source>J_x rows −∂g_i/∂X</source>
        <translation>vrste J_x: −∂g_i/∂X</translation>
    </message>
    <message>
        <source>q̇ = J·Ẋ, J = J_q⁻¹·J_x</source>
        <translation>q̇ = J·Ẋ, J = J_q⁻¹·J_x</translation>
    </message>
    <message>
        <source>other assembly mode (same inputs)</source>
        <translation>drugi način sklapanja (isti ulazi)</translation>
    </message>
    <message>
        <source>leg 1: other working mode (same platform pose)</source>
        <translation>noga 1: drugi radni režim (ista poza platforme)</translation>
    </message>
    <message>
        <source>leg 2: other working mode (same platform pose)</source>
        <translation>noga 2: drugi radni režim (ista poza platforme)</translation>
    </message>
    <message>
        <source>leg 3: other working mode (same platform pose)</source>
        <translation>noga 3: drugi radni režim (ista poza platforme)</translation>
    </message>
    <message>
        <source>%1 = %2 is invalid: it must be a whole number.</source>
        <translation>%1 = %2 nije dopušteno: mora biti ceo broj.</translation>
    </message>
    <message>
        <source>The planar parallel mechanism has no parameter named &apos;%1&apos;.</source>
        <translation>Ravanski paralelni mehanizam nema parametar „%1”.</translation>
    </message>
    <message>
        <source>platform: 0 a point (2 DOF), 1 constant orientation (2 DOF), 2 free (3 DOF)</source>
        <translation>platforma: 0 tačka (2 stepena slobode), 1 stalna orijentacija (2 stepena slobode), 2 slobodna (3 stepena slobode)</translation>
    </message>
    <message>
        <source>leg 1: type (0 R̲RR, 1 P̲RR, 2 RP̲R, 3 П̲RR)</source>
        <translation>noga 1: tip (0 R̲RR, 1 P̲RR, 2 RP̲R, 3 P̲RR)</translation>
    </message>
    <message>
        <source>leg 1: base point A₁, x</source>
        <translation>noga 1: tačka osnove A₁, x</translation>
    </message>
    <message>
        <source>leg 1: base point A₁, y</source>
        <translation>noga 1: tačka osnove A₁, y</translation>
    </message>
    <message>
        <source>leg 1: platform point B₁ in the platform frame, x</source>
        <translation>noga 1: tačka platforme B₁ u sistemu platforme, x</translation>
    </message>
    <message>
        <source>leg 1: platform point B₁ in the platform frame, y</source>
        <translation>noga 1: tačka platforme B₁ u sistemu platforme, y</translation>
    </message>
    <message>
        <source>leg 1: crank length (R̲RR)</source>
        <translation>noga 1: dužina poluge (R̲RR)</translation>
    </message>
    <message>
        <source>leg 1: distal link length</source>
        <translation>noga 1: dužina distalne spojke</translation>
    </message>
    <message>
        <source>leg 1: direction of the guide (P̲RR) or of the П-joint base (П̲RR)</source>
        <translation>noga 1: pravac vođice (P̲RR) ili osnove P-zgloba (P̲RR)</translation>
    </message>
    <message>
        <source>leg 1: П-joint crank (lever) length</source>
        <translation>noga 1: dužina poluge P-zgloba</translation>
    </message>
    <message>
        <source>leg 1: П-joint ratio k = b/a</source>
        <translation>noga 1: odnos P-zgloba k = b/a</translation>
    </message>
    <message>
        <source>leg 1: working mode (+1 elbow left of A₁→P₁; P̲RR: sign in q = B ± √…)</source>
        <translation>noga 1: radni režim (+1 lakat levo od A₁→P₁; P̲RR: znak u q = B ± √…)</translation>
    </message>
    <message>
        <source>leg 2: type (0 R̲RR, 1 P̲RR, 2 RP̲R, 3 П̲RR)</source>
        <translation>noga 2: tip (0 R̲RR, 1 P̲RR, 2 RP̲R, 3 P̲RR)</translation>
    </message>
    <message>
        <source>leg 2: base point A₂, x</source>
        <translation>noga 2: tačka osnove A₂, x</translation>
    </message>
    <message>
        <source>leg 2: base point A₂, y</source>
        <translation>noga 2: tačka osnove A₂, y</translation>
    </message>
    <message>
        <source>leg 2: platform point B₂ in the platform frame, x</source>
        <translation>noga 2: tačka platforme B₂ u sistemu platforme, x</translation>
    </message>
    <message>
        <source>leg 2: platform point B₂ in the platform frame, y</source>
        <translation>noga 2: tačka platforme B₂ u sistemu platforme, y</translation>
    </message>
    <message>
        <source>leg 2: crank length (R̲RR)</source>
        <translation>noga 2: dužina poluge (R̲RR)</translation>
    </message>
    <message>
        <source>leg 2: distal link length</source>
        <translation>noga 2: dužina distalne spojke</translation>
    </message>
    <message>
        <source>leg 2: direction of the guide (P̲RR) or of the П-joint base (П̲RR)</source>
        <translation>noga 2: pravac vođice (P̲RR) ili osnove P-zgloba (P̲RR)</translation>
    </message>
    <message>
        <source>leg 2: П-joint crank (lever) length</source>
        <translation>noga 2: dužina poluge P-zgloba</translation>
    </message>
    <message>
        <source>leg 2: П-joint ratio k = b/a</source>
        <translation>noga 2: odnos P-zgloba k = b/a</translation>
    </message>
    <message>
        <source>leg 2: working mode (+1 elbow left of A₂→P₂; P̲RR: sign in q = B ± √…)</source>
        <translation>noga 2: radni režim (+1 lakat levo od A₂→P₂; P̲RR: znak u q = B ± √…)</translation>
    </message>
    <message>
        <source>leg 3: type (0 R̲RR, 1 P̲RR, 2 RP̲R, 3 П̲RR)</source>
        <translation>noga 3: tip (0 R̲RR, 1 P̲RR, 2 RP̲R, 3 P̲RR)</translation>
    </message>
    <message>
        <source>leg 3: base point A₃, x</source>
        <translation>noga 3: tačka osnove A₃, x</translation>
    </message>
    <message>
        <source>leg 3: base point A₃, y</source>
        <translation>noga 3: tačka osnove A₃, y</translation>
    </message>
    <message>
        <source>leg 3: platform point B₃ in the platform frame, x</source>
        <translation>noga 3: tačka platforme B₃ u sistemu platforme, x</translation>
    </message>
    <message>
        <source>leg 3: platform point B₃ in the platform frame, y</source>
        <translation>noga 3: tačka platforme B₃ u sistemu platforme, y</translation>
    </message>
    <message>
        <source>leg 3: crank length (R̲RR)</source>
        <translation>noga 3: dužina poluge (R̲RR)</translation>
    </message>
    <message>
        <source>leg 3: distal link length</source>
        <translation>noga 3: dužina distalne spojke</translation>
    </message>
    <message>
        <source>leg 3: direction of the guide (P̲RR) or of the П-joint base (П̲RR)</source>
        <translation>noga 3: pravac vođice (P̲RR) ili osnove P-zgloba (P̲RR)</translation>
    </message>
    <message>
        <source>leg 3: П-joint crank (lever) length</source>
        <translation>noga 3: dužina poluge P-zgloba</translation>
    </message>
    <message>
        <source>leg 3: П-joint ratio k = b/a</source>
        <translation>noga 3: odnos P-zgloba k = b/a</translation>
    </message>
    <message>
        <source>leg 3: working mode (+1 elbow left of A₃→P₃; P̲RR: sign in q = B ± √…)</source>
        <translation>noga 3: radni režim (+1 lakat levo od A₃→P₃; P̲RR: znak u q = B ± √…)</translation>
    </message>
    <message>
        <source>assembly mode: 2 DOF +1 platform left of C₁→C₂, −1 right; 3 DOF the n-th solution in order of φ</source>
        <translation>način sklapanja: za 2 stepena slobode +1 platforma levo od C₁→C₂, −1 desno; za 3 — n-to rešenje po rastućem φ</translation>
    </message>
    <message>
        <source>platform angle φ of the workspace map (3 DOF)</source>
        <translation>ugao platforme φ za mapu radnog prostora (3 stepena slobode)</translation>
    </message>
    <message>
        <source>%1 must be less than %2.</source>
        <translation>%1 mora biti manje od %2.</translation>
    </message>
    <message>
        <source>The range of crank %1 spans more than one turn (360°).</source>
        <translation>Opseg poluge %1 veći je od jednog obrta (360°).</translation>
    </message>
    <message>
        <source>%1 must be positive: it is the length of strut %2.</source>
        <translation>%1 mora biti pozitivno: to je dužina šipke %2.</translation>
    </message>
    <message>
        <source>The diagonal of П-joint %1 must stay strictly between %2 mm and %3 mm (θ between −90° and 90°).</source>
        <translation>Dijagonala P-zgloba %1 mora biti strogo između %2 mm i %3 mm (θ između −90° i 90°).</translation>
    </message>
    <message>
        <source>A platform of constant orientation needs P̲RR or П̲RR legs: leg %1&apos;s distal parallelogram must hang from a body that does not turn.</source>
        <translation>Platformi stalne orijentacije potrebne su noge P̲RR ili P̲RR: distalni paralelogram noge %1 mora visiti o telu koje se ne okreće.</translation>
    </message>
    <message>
        <source>The assembly mode of a 3-DOF platform counts the solutions from 1.</source>
        <translation>Način sklapanja platforme sa 3 stepena slobode broji rešenja od 1.</translation>
    </message>
    <message>
        <source>The platform points B₁, B₂, B₃ coincide: the platform&apos;s angle is undetermined.</source>
        <translation>Tačke platforme B₁, B₂, B₃ se poklapaju: ugao platforme nije određen.</translation>
    </message>
    <message>
        <source>The mechanism cannot be assembled anywhere in its input ranges and modes.</source>
        <translation>Mehanizam se ne može sklopiti nigde u svojim opsezima ulaza i režimima.</translation>
    </message>
    <message>
        <source>input of leg 1 (actuated)</source>
        <translation>ulaz noge 1 (pogonski)</translation>
    </message>
    <message>
        <source>input of leg 2 (actuated)</source>
        <translation>ulaz noge 2 (pogonski)</translation>
    </message>
    <message>
        <source>input of leg 3 (actuated)</source>
        <translation>ulaz noge 3 (pogonski)</translation>
    </message>
    <message>
        <source>The number of inputs does not match the legs.</source>
        <translation>Broj ulaza ne odgovara broju nogu.</translation>
    </message>
    <message>
        <source>%1 = %2 is outside its range [%3, %4].</source>
        <translation>%1 = %2 je izvan svog opsega [%3, %4].</translation>
    </message>
    <message>
        <source>The П-joint of leg %1 cannot take the diagonal %2 = %3 mm.</source>
        <translation>P-zglob noge %1 ne može imati dijagonalu %2 = %3 mm.</translation>
    </message>
    <message>
        <source>The legs cannot be assembled at these inputs in the design&apos;s working and assembly modes.</source>
        <translation>Pri ovim ulazima noge se ne mogu sklopiti u radnim režimima i načinu sklapanja projekta.</translation>
    </message>
    <message>
        <source>At these inputs the platform has %1 assembly modes in the design&apos;s working modes, fewer than assembly = %2.</source>
        <translation>Pri ovim ulazima platforma ima %1 načina sklapanja u radnim režimima projekta, manje od assembly = %2.</translation>
    </message>
    <message>
        <source>(%1, %2) mm, φ = %3°</source>
        <translation>(%1, %2) mm, φ = %3°</translation>
    </message>
    <message>
        <source>The platform cannot reach %1 in this assembly mode: the legs would pass through a direct singularity; switch the assembly mode to go on.</source>
        <translation>Platforma ne može dostići %1 u ovom načinu sklapanja: noge bi prošle kroz singularitet direktne kinematike; promenite način sklapanja da biste nastavili.</translation>
    </message>
    <message>
        <source>the input of leg %1 would leave its range</source>
        <translation>ulaz noge %1 izašao bi iz svog opsega</translation>
    </message>
    <message>
        <source>the input of leg %1 is undetermined there</source>
        <translation>ulaz noge %1 tu nije određen</translation>
    </message>
    <message>
        <source>leg %1 cannot reach it</source>
        <translation>noga %1 ne može da je dostigne</translation>
    </message>
    <message>
        <source>a leg&apos;s proximal and distal links in line</source>
        <translation>proksimalna i distalna spojka noge u liniji</translation>
    </message>
    <message>
        <source>the platform gains a freedom</source>
        <translation>platforma dobija slobodu</translation>
    </message>
    <message>
        <source>crank %1</source>
        <translation>poluga %1</translation>
    </message>
    <message>
        <source>strut %1, motor body</source>
        <translation>šipka %1, kućište motora</translation>
    </message>
    <message>
        <source>strut %1, rod</source>
        <translation>šipka %1, klip</translation>
    </message>
    <message>
        <source>П-joint %1: crank OC</source>
        <translation>P-zglob %1: poluga OC</translation>
    </message>
    <message>
        <source>П-joint %1: coupler</source>
        <translation>P-zglob %1: spojka</translation>
    </message>
    <message>
        <source>П-joint %1: motor body</source>
        <translation>P-zglob %1: kućište motora</translation>
    </message>
    <message>
        <source>П-joint %1: screw</source>
        <translation>P-zglob %1: vreteno</translation>
    </message>
    <message>
        <source>link %1, parallel</source>
        <translation>spojka %1, paralelna</translation>
    </message>
    <message>
        <source>planar parallel mechanism: legs from the leg library joined at the platform</source>
        <translation>ravanski paralelni mehanizam: noge iz biblioteke nogu spojene platformom</translation>
    </message>
    <message>
        <source>Planar parallel mechanism (leg library)</source>
        <translation>Ravanski paralelni mehanizam (biblioteka nogu)</translation>
    </message>
    <message>
        <source>leg 1: lower limit of the input (P̲RR, RP̲R, П̲RR)</source>
        <translation>noga 1: donja granica ulaza (P̲RR, RP̲R, P̲RR)</translation>
    </message>
    <message>
        <source>leg 1: upper limit of the input (P̲RR, RP̲R, П̲RR)</source>
        <translation>noga 1: gornja granica ulaza (P̲RR, RP̲R, P̲RR)</translation>
    </message>
    <message>
        <source>leg 1: lower limit of the crank angle (R̲RR)</source>
        <translation>noga 1: donja granica ugla poluge (R̲RR)</translation>
    </message>
    <message>
        <source>leg 1: upper limit of the crank angle (R̲RR)</source>
        <translation>noga 1: gornja granica ugla poluge (R̲RR)</translation>
    </message>
    <message>
        <source>leg 2: lower limit of the input (P̲RR, RP̲R, П̲RR)</source>
        <translation>noga 2: donja granica ulaza (P̲RR, RP̲R, P̲RR)</translation>
    </message>
    <message>
        <source>leg 2: upper limit of the input (P̲RR, RP̲R, П̲RR)</source>
        <translation>noga 2: gornja granica ulaza (P̲RR, RP̲R, P̲RR)</translation>
    </message>
    <message>
        <source>leg 2: lower limit of the crank angle (R̲RR)</source>
        <translation>noga 2: donja granica ugla poluge (R̲RR)</translation>
    </message>
    <message>
        <source>leg 2: upper limit of the crank angle (R̲RR)</source>
        <translation>noga 2: gornja granica ugla poluge (R̲RR)</translation>
    </message>
    <message>
        <source>leg 3: lower limit of the input (P̲RR, RP̲R, П̲RR)</source>
        <translation>noga 3: donja granica ulaza (P̲RR, RP̲R, P̲RR)</translation>
    </message>
    <message>
        <source>leg 3: upper limit of the input (P̲RR, RP̲R, П̲RR)</source>
        <translation>noga 3: gornja granica ulaza (P̲RR, RP̲R, P̲RR)</translation>
    </message>
    <message>
        <source>leg 3: lower limit of the crank angle (R̲RR)</source>
        <translation>noga 3: donja granica ugla poluge (R̲RR)</translation>
    </message>
    <message>
        <source>leg 3: upper limit of the crank angle (R̲RR)</source>
        <translation>noga 3: gornja granica ugla poluge (R̲RR)</translation>
    </message>
    <message>
        <source>The drag stops short of the O↔X crossing at x_CD − x_AB = s = %1 mm, where the rods are parallel and the platform can swing: switch the form to go on.</source>
        <translation>Prevlačenje se zaustavlja pre prelaza O↔X pri x_CD − x_AB = s = %1 mm, gde su šipke paralelne i platforma može da se njiše: promenite oblik da biste nastavili.</translation>
    </message>
    <message>
        <source>eq. %1 of the П-joint document</source>
        <translation>jed. %1 rada o P-zglobu</translation>
    </message>
    <message>
        <source>fig. %1 of the П-joint document</source>
        <translation>sl. %1 rada o P-zglobu</translation>
    </message>
    <message>
        <source>the П-joint document</source>
        <translation>rad o P-zglobu</translation>
    </message>
    <message>
        <source>eq. %1 of the MOMA document</source>
        <translation>jed. %1 rada o MOMA</translation>
    </message>
    <message>
        <source>fig. %1 of the MOMA document</source>
        <translation>sl. %1 rada o MOMA</translation>
    </message>
    <message>
        <source>the MOMA document</source>
        <translation>rad o MOMA</translation>
    </message>
    <message>
        <source>eq. %1 of the O-X glide document</source>
        <translation>jed. %1 rada o O-X glide</translation>
    </message>
    <message>
        <source>fig. %1 of the O-X glide document</source>
        <translation>sl. %1 rada o O-X glide</translation>
    </message>
    <message>
        <source>the O-X glide document</source>
        <translation>rad o O-X glide</translation>
    </message>
    <message>
        <source>eq. %1 of the four-bar and mobility document</source>
        <translation>jed. %1 rada o zglobnom četvorouglu i pokretljivosti</translation>
    </message>
    <message>
        <source>fig. %1 of the four-bar and mobility document</source>
        <translation>sl. %1 rada o zglobnom četvorouglu i pokretljivosti</translation>
    </message>
    <message>
        <source>the four-bar and mobility document</source>
        <translation>rad o zglobnom četvorouglu i pokretljivosti</translation>
    </message>
    <message>
        <source>PKM Studio&apos;s model</source>
        <translation>model programa PKM Studio</translation>
    </message>
    <message>
        <source>Input Jacobian of leg 1 (0: inverse singularity)</source>
        <translation>Jakobijan ulaza noge 1 (0: singularitet inverzne kinematike)</translation>
    </message>
    <message>
        <source>Input Jacobian of leg 2 (0: inverse singularity)</source>
        <translation>Jakobijan ulaza noge 2 (0: singularitet inverzne kinematike)</translation>
    </message>
    <message>
        <source>Output Jacobian (0: direct singularity)</source>
        <translation>Jakobijan izlaza (0: singularitet direktne kinematike)</translation>
    </message>
    <message>
        <source>Determinant of J</source>
        <translation>Determinanta J</translation>
    </message>
    <message>
        <source>J = J_q⁻¹·J_x maps lengths to angles, so det J is in rad²/mm², not dimensionless as MOMA&apos;s and the O-X glide&apos;s.</source>
        <translation>J = J_q⁻¹·J_x preslikava dužine u uglove, pa je det J u rad²/mm², a ne bezdimenzionalan kao kod MOMA i O-X glide.</translation>
    </message>
    <message>
        <source>Transmission angle between the distal links</source>
        <translation>Ugao prenosa između spojki</translation>
    </message>
    <message>
        <source>Distance from the inverse singularities</source>
        <translation>Udaljenost od singulariteta inverzne kinematike</translation>
    </message>
    <message>
        <source>Distance from the direct singularities</source>
        <translation>Udaljenost od singulariteta direktne kinematike</translation>
    </message>
    <message>
        <source>Transmission angle γ at C</source>
        <translation>Ugao prenosa γ u C</translation>
    </message>
    <message>
        <source>Angle at D from DA to DB</source>
        <translation>Ugao u D od DA do DB</translation>
    </message>
    <message>
        <source>Rocker angle</source>
        <translation>Ugao klackalice</translation>
    </message>
    <message>
        <source>The document takes the arctan of the ratio, which is 180° off wherever CD − BC·cos γ &lt; 0; the program uses atan2.</source>
        <translation>Rad uzima arctg količnika, što greši za 180° gde god je CD − BC·cos γ &lt; 0; program koristi atan2.</translation>
    </message>
    <message>
        <source>Angle at B</source>
        <translation>Ugao u B</translation>
    </message>
    <message>
        <source>Transfer function dδ/dα</source>
        <translation>Prenosna funkcija dδ/dα</translation>
    </message>
    <message>
        <source>The document&apos;s (8) and (9) give the rocker&apos;s counter-clockwise rate dθ₃/dt = −dδ/dt; the program&apos;s ω₃ and i₃₁ are their negatives.</source>
        <translation>Jednačine (8) i (9) iz rada daju brzinu klackalice suprotno od kazaljke na satu dθ₃/dt = −dδ/dt; ω₃ i i₃₁ u programu su iste veličine sa suprotnim znakom.</translation>
    </message>
    <message>
        <source>Rocker angular velocity</source>
        <translation>Ugaona brzina klackalice</translation>
    </message>
    <message>
        <source>Rocker angular acceleration at constant ω₁</source>
        <translation>Ugaono ubrzanje klackalice pri konstantnoj ω₁</translation>
    </message>
    <message>
        <source>The document&apos;s (14) agrees with neither sign of the exact second derivative; the program differentiates the loop closure twice.</source>
        <translation>Jednačina (14) iz rada se ne slaže sa tačnim drugim izvodom ni sa jednim znakom; program dvaput diferencira jednačinu zatvaranja konture.</translation>
    </message>
    <message>
        <source>Input Jacobian (0: inverse singularity)</source>
        <translation>Jakobijan ulaza (0: singularitet inverzne kinematike)</translation>
    </message>
    <message>
        <source>Projection on guide %1</source>
        <translation>Projekcija na vođicu %1</translation>
    </message>
    <message>
        <source>Reach of link %1</source>
        <translation>Domet spojke %1</translation>
    </message>
    <message>
        <source>Inverse kinematics of leg %1</source>
        <translation>Inverzna kinematika noge %1</translation>
    </message>
    <message>
        <source>The program takes B_i² − C_i as l_i² − (a_i × (P − R_i))², the same number without cancelling two large ones.</source>
        <translation>Program računa B_i² − C_i kao l_i² − (a_i × (P − R_i))²: isti broj, bez oduzimanja dva velika broja.</translation>
    </message>
    <message>
        <source>Direct kinematics: P along Z₁→Z₂</source>
        <translation>Direktna kinematika: P duž Z₁→Z₂</translation>
    </message>
    <message>
        <source>The document&apos;s (10–12) divide by x_Z2 − x_Z1 and fail with the slider joints one above the other; the program intersects the circles measured along Z₁→Z₂: P = Z₁ + s·u + σ·h·n, h = √(l₁² − s²).</source>
        <translation>Jednačine (10–12) iz rada dele sa x_Z2 − x_Z1 i ne važe kad su zglobovi klizača jedan iznad drugog; program seče krugove mereći duž Z₁→Z₂: P = Z₁ + s·u + σ·h·n, h = √(l₁² − s²).</translation>
    </message>
    <message>
        <source>From J_p·ṗ + J_x·Ṗ = 0 the program&apos;s J is −J_p⁻¹·J_x; the document&apos;s (21) has no minus sign. For the 2×2 J the determinant is the same.</source>
        <translation>Iz J_p·ṗ + J_x·Ṗ = 0 u programu je J = −J_p⁻¹·J_x; u jednačini (21) iz rada nema minusa. Za matricu J 2×2 determinanta je ista.</translation>
    </message>
    <message>
        <source>Run of a rod along the guides</source>
        <translation>Projekcija šipke duž vođica</translation>
    </message>
    <message>
        <source>Inverse kinematics, %1 form</source>
        <translation>Inverzna kinematika, oblik %1</translation>
    </message>
    <message>
        <source>Direct kinematics, both forms</source>
        <translation>Direktna kinematika, oba oblika</translation>
    </message>
    <message>
        <source>The document prints “+ s” in the X form&apos;s direct kinematics, which contradicts its own inverse kinematics; with “− s” both forms return their poses exactly. The sign of x_CD − x_AB − s is the form.</source>
        <translation>Rad u direktnoj kinematici oblika X štampa „+ s”, što protivreči njegovoj inverznoj kinematici; sa „− s” oba oblika tačno vraćaju svoje položaje. Znak x_CD − x_AB − s je oblik.</translation>
    </message>
    <message>
        <source>J = −J_q⁻¹·J_x = [1, y/u₁; 1, y/u₂] from the constraints (x ∓ s/2 − x_i)² + y² − l² = 0; w = 0 (rods perpendicular to the guides or parallel to each other) is singular.</source>
        <translation>J = −J_q⁻¹·J_x = [1, y/u₁; 1, y/u₂] iz jednačina veza (x ∓ s/2 − x_i)² + y² − l² = 0; w = 0 (šipke upravne na vođice ili paralelne međusobno) je singularitet.</translation>
    </message>
    <message>
        <source>Condition number of J</source>
        <translation>Broj uslovljenosti J</translation>
    </message>
    <message>
        <source>Inverse kinematics</source>
        <translation>Inverzna kinematika</translation>
    </message>
    <message>
        <source>Direct kinematics</source>
        <translation>Direktna kinematika</translation>
    </message>
    <message>
        <source>Transmission angle</source>
        <translation>Ugao prenosa</translation>
    </message>
    <message>
        <source>Output torque at F_max</source>
        <translation>Izlazni moment pri F_max</translation>
    </message>
    <message>
        <source>J in mm/rad times F in N gives N·mm; 10⁻³ turns it into N·m.</source>
        <translation>J u mm/rad puta F u N daje N·mm; činilac 10⁻³ pretvara to u N·m.</translation>
    </message>
    <message>
        <source>Output resolution per motor step</source>
        <translation>Izlazna rezolucija po koraku motora</translation>
    </message>
    <message>
        <source>Motor torque at F_max</source>
        <translation>Moment motora pri F_max</translation>
    </message>
    <message>
        <source>Table 1 gives no screw efficiency η; the presets assume 0.4.</source>
        <translation>Tabela 1 ne daje stepen iskorišćenja vretena η; primeri uzimaju 0,4.</translation>
    </message>
    <message>
        <source>The document&apos;s acceleration (19–20) drops θ̈ from the first term and writes θ̇ where θ̇² belongs; the program uses d̈ = J·θ̈ + (∂J/∂θ)·θ̇², which agrees with the numerical second derivative.</source>
        <translation>U ubrzanju (19–20) iz rada prvom članu nedostaje θ̈, a umesto θ̇² piše θ̇; program koristi d̈ = J·θ̈ + (∂J/∂θ)·θ̇², što se slaže sa numeričkim drugim izvodom.</translation>
    </message>
    <message>
        <source>At the platform&apos;s position %1 the legs would hold it only in the other assembly mode.</source>
        <translation>U položaju platforme %1 noge bi je držale samo u drugom načinu sklapanja.</translation>
    </message>
    <message>
        <source>At the platform&apos;s position %1 leg %2 cannot reach it: its platform point is too far from its base point A%2 for its links.</source>
        <translation>U položaju platforme %1 noga %2 ne može da je dostigne: njena tačka platforme je predaleko od tačke osnove A%2 za njene članove.</translation>
    </message>
    <message>
        <source>At the platform&apos;s position %1 leg %2 cannot reach it: its platform point is too near its base point A%2 for its links.</source>
        <translation>U položaju platforme %1 noga %2 ne može da je dostigne: njena tačka platforme je preblizu tački osnove A%2 za njene članove.</translation>
    </message>
    <message>
        <source>At the platform&apos;s position %1 leg %2 cannot reach it: its input would leave its range.</source>
        <translation>U položaju platforme %1 noga %2 ne može da je dostigne: njen ulaz izašao bi iz svog opsega.</translation>
    </message>
    <message>
        <source>At the platform&apos;s position %1 the input of leg %2 is undetermined.</source>
        <translation>U položaju platforme %1 ulaz noge %2 nije određen.</translation>
    </message>
    <message>
        <source>drag to move the base point A%1 (changes the design)</source>
        <translation>prevucite da pomerite tačku osnove A%1 (menja konstrukciju)</translation>
    </message>
    <message>
        <source>drag to move the platform point B%1 (changes the design)</source>
        <translation>prevucite da pomerite tačku platforme B%1 (menja konstrukciju)</translation>
    </message>
    <message>
        <source>Leg %1 (%2): constraint</source>
        <translation>Noga %1 (%2): jednačina veze</translation>
    </message>
    <message>
        <source>Leg %1 (%2): the П-joint&apos;s angle</source>
        <translation>Noga %1 (%2): ugao P-zgloba</translation>
    </message>
    <message>
        <source>Leg %1 (%2): the П-joint&apos;s Jacobian</source>
        <translation>Noga %1 (%2): jakobijan P-zgloba</translation>
    </message>
    <message>
        <source>The leg&apos;s row of J_x carries this J as a factor, so the П-joint&apos;s own singularity (θ = ±90°) is a direct singularity of the whole mechanism (the П-joint document, section 4).</source>
        <translation>Red noge u J_x sadrži ovaj J kao činilac, pa je singularitet samog P-zgloba (θ = ±90°) singularitet direktne kinematike celog mehanizma (rad o P-zglobu, odeljak 4).</translation>
    </message>
    <message>
        <source>Leg %1 (%2): input Jacobian (0: inverse singularity)</source>
        <translation>Noga %1 (%2): jakobijan ulaza (0: singularitet inverzne kinematike)</translation>
    </message>
    <message>
        <source>assembly mode 1 (same inputs)</source>
        <translation>način sklapanja 1 (isti ulazi)</translation>
    </message>
    <message>
        <source>assembly mode 2 (same inputs)</source>
        <translation>način sklapanja 2 (isti ulazi)</translation>
    </message>
    <message>
        <source>assembly mode 3 (same inputs)</source>
        <translation>način sklapanja 3 (isti ulazi)</translation>
    </message>
    <message>
        <source>assembly mode 4 (same inputs)</source>
        <translation>način sklapanja 4 (isti ulazi)</translation>
    </message>
    <message>
        <source>assembly mode 5 (same inputs)</source>
        <translation>način sklapanja 5 (isti ulazi)</translation>
    </message>
    <message>
        <source>assembly mode 6 (same inputs)</source>
        <translation>način sklapanja 6 (isti ulazi)</translation>
    </message>
    <message>
        <source>leg 1 stretched (crank and link in line)</source>
        <translation>noga 1 opružena (poluga i spojka na istoj pravoj)</translation>
    </message>
    <message>
        <source>leg 1 folded (crank and link in line)</source>
        <translation>noga 1 presavijena (poluga i spojka na istoj pravoj)</translation>
    </message>
    <message>
        <source>leg 2 stretched (crank and link in line)</source>
        <translation>noga 2 opružena (poluga i spojka na istoj pravoj)</translation>
    </message>
    <message>
        <source>leg 2 folded (crank and link in line)</source>
        <translation>noga 2 presavijena (poluga i spojka na istoj pravoj)</translation>
    </message>
    <message>
        <source>leg 3 stretched (crank and link in line)</source>
        <translation>noga 3 opružena (poluga i spojka na istoj pravoj)</translation>
    </message>
    <message>
        <source>leg 3 folded (crank and link in line)</source>
        <translation>noga 3 presavijena (poluga i spojka na istoj pravoj)</translation>
    </message>
    <message>
        <source>link 3 ⟂ guide 3</source>
        <translation>spojka 3 ⟂ vođici 3</translation>
    </message>
    <message>
        <source>distal lines through one point</source>
        <translation>distalne prave kroz jednu tačku</translation>
    </message>
    <message>
        <source>actuator 1: maximum force</source>
        <translation>pogon 1: najveća sila</translation>
    </message>
    <message>
        <source>actuator 2: maximum force</source>
        <translation>pogon 2: najveća sila</translation>
    </message>
    <message>
        <source>actuator 3: maximum force</source>
        <translation>pogon 3: najveća sila</translation>
    </message>
    <message>
        <source>actuator 1: maximum speed</source>
        <translation>pogon 1: najveća brzina</translation>
    </message>
    <message>
        <source>actuator 2: maximum speed</source>
        <translation>pogon 2: najveća brzina</translation>
    </message>
    <message>
        <source>actuator 3: maximum speed</source>
        <translation>pogon 3: najveća brzina</translation>
    </message>
    <message>
        <source>actuator 1: step (resolution)</source>
        <translation>pogon 1: korak (rezolucija)</translation>
    </message>
    <message>
        <source>actuator 2: step (resolution)</source>
        <translation>pogon 2: korak (rezolucija)</translation>
    </message>
    <message>
        <source>actuator 3: step (resolution)</source>
        <translation>pogon 3: korak (rezolucija)</translation>
    </message>
    <message>
        <source>actuator 1: axial stiffness</source>
        <translation>pogon 1: aksijalna krutost</translation>
    </message>
    <message>
        <source>actuator 2: axial stiffness</source>
        <translation>pogon 2: aksijalna krutost</translation>
    </message>
    <message>
        <source>actuator 3: axial stiffness</source>
        <translation>pogon 3: aksijalna krutost</translation>
    </message>
    <message>
        <source>actuator 1: maximum torque</source>
        <translation>pogon 1: najveći moment</translation>
    </message>
    <message>
        <source>actuator 2: maximum torque</source>
        <translation>pogon 2: najveći moment</translation>
    </message>
    <message>
        <source>actuator 3: maximum torque</source>
        <translation>pogon 3: najveći moment</translation>
    </message>
    <message>
        <source>actuator 1: maximum angular speed</source>
        <translation>pogon 1: najveća ugaona brzina</translation>
    </message>
    <message>
        <source>actuator 2: maximum angular speed</source>
        <translation>pogon 2: najveća ugaona brzina</translation>
    </message>
    <message>
        <source>actuator 3: maximum angular speed</source>
        <translation>pogon 3: najveća ugaona brzina</translation>
    </message>
    <message>
        <source>actuator 1: angular step (resolution)</source>
        <translation>pogon 1: ugaoni korak (rezolucija)</translation>
    </message>
    <message>
        <source>actuator 2: angular step (resolution)</source>
        <translation>pogon 2: ugaoni korak (rezolucija)</translation>
    </message>
    <message>
        <source>actuator 3: angular step (resolution)</source>
        <translation>pogon 3: ugaoni korak (rezolucija)</translation>
    </message>
    <message>
        <source>actuator 1: torsional stiffness</source>
        <translation>pogon 1: torziona krutost</translation>
    </message>
    <message>
        <source>actuator 2: torsional stiffness</source>
        <translation>pogon 2: torziona krutost</translation>
    </message>
    <message>
        <source>actuator 3: torsional stiffness</source>
        <translation>pogon 3: torziona krutost</translation>
    </message>
    <message>
        <source>largest force in the weakest direction</source>
        <translation>najveća sila u najslabijem pravcu</translation>
    </message>
    <message>
        <source>largest force in the strongest direction</source>
        <translation>najveća sila u najjačem pravcu</translation>
    </message>
    <message>
        <source>largest speed in the slowest direction</source>
        <translation>najveća brzina u najsporijem pravcu</translation>
    </message>
    <message>
        <source>largest speed in the fastest direction</source>
        <translation>najveća brzina u najbržem pravcu</translation>
    </message>
    <message>
        <source>largest error from half a step per actuator</source>
        <translation>najveća greška od pola koraka svakog pogona</translation>
    </message>
    <message>
        <source>stiffness K = Jᵀ·K_q·J (N/mm, N/rad, N·mm/rad)</source>
        <translation>krutost K = Jᵀ·K_q·J (N/mm, N/rad, N·mm/rad)</translation>
    </message>
    <message>
        <source>stiffness K = Jᵀ·K_q·J</source>
        <translation>krutost K = Jᵀ·K_q·J</translation>
    </message>
    <message>
        <source>stiffness in the weakest direction</source>
        <translation>krutost u najslabijem pravcu</translation>
    </message>
    <message>
        <source>measured static stiffness of the whole joint (the document)</source>
        <translation>izmerena statička krutost celog zgloba (iz dokumenta)</translation>
    </message>
    <message>
        <source>N/mm</source>
        <translation>N/mm</translation>
    </message>
    <message>
        <source>axial stiffness of the actuator</source>
        <translation>aksijalna krutost pogona</translation>
    </message>
    <message>
        <source>measured static stiffness of the joint</source>
        <translation>izmerena statička krutost zgloba</translation>
    </message>
    <message>
        <source>load: torque on the output link</source>
        <translation>opterećenje: moment na izlaznom članku</translation>
    </message>
    <message>
        <source>load: force on the platform, x</source>
        <translation>opterećenje: sila na platformi, x</translation>
    </message>
    <message>
        <source>load: force on the platform, y</source>
        <translation>opterećenje: sila na platformi, y</translation>
    </message>
    <message>
        <source>load: moment on the platform</source>
        <translation>opterećenje: moment na platformi</translation>
    </message>
    <message>
        <source>deflection under the load (actuators&apos; compliance)</source>
        <translation>ugib pod opterećenjem (popustljivost aktuatora)</translation>
    </message>
    <message>
        <source>deflection of the platform point under the load</source>
        <translation>pomeraj tačke platforme pod opterećenjem</translation>
    </message>
    <message>
        <source>length of the deflection under the load</source>
        <translation>veličina pomeraja pod opterećenjem</translation>
    </message>
    <message>
        <source>rotation of the platform under the load</source>
        <translation>zaokret platforme pod opterećenjem</translation>
    </message>
    <message>
        <source>undefined at this singular pose</source>
        <translation>nedefinisano u ovom singularnom položaju</translation>
    </message>
    <message>
        <source>cut at the edge of the drawing</source>
        <translation>odsečeno na ivici crteža</translation>
    </message>
    <message>
        <source>velocity: 1 mm ≙ %1 mm/s</source>
        <translation>brzina: 1 mm ≙ %1 mm/s</translation>
    </message>
    <message>
        <source>unbounded: the locked actuators do not hold the platform (direct singularity)</source>
        <translation>neograničeno: zakočeni aktuatori ne drže platformu (direktna singularnost)</translation>
    </message>
    <message>
        <source>force: 1 mm ≙ %1 N</source>
        <translation>sila: 1 mm ≙ %1 N</translation>
    </message>
    <message>
        <source>unbounded: a stretched leg holds any force along it (inverse singularity)</source>
        <translation>neograničeno: ispružena noga drži svaku silu duž sebe (inverzna singularnost)</translation>
    </message>
    <message>
        <source>The design has no parameter named &apos;%1&apos; to give a tolerance.</source>
        <translation>Konstrukcija nema parametar „%1” kome bi se zadala tolerancija.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; (%2) is not a geometric parameter: tolerances apply to the lengths, positions and angles of the design.</source>
        <translation>„%1” (%2) nije geometrijski parametar: tolerancije se zadaju dužinama, položajima i uglovima konstrukcije.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is derived from other parameters: give the tolerances of the parameters it is made of.</source>
        <translation>„%1” se izvodi iz drugih parametara: zadajte tolerancije parametara od kojih nastaje.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; has no say in this design, so a tolerance on it changes nothing.</source>
        <translation>„%1” ne utiče na ovu konstrukciju, pa tolerancija na njemu ništa ne menja.</translation>
    </message>
    <message>
        <source>The tolerance of &apos;%1&apos; must be a finite number ≥ 0.</source>
        <translation>Tolerancija za „%1” mora biti konačan broj ≥ 0.</translation>
    </message>
    <message>
        <source>The tolerance ±%2 of &apos;%1&apos; takes it to %3, outside its allowed values.</source>
        <translation>Tolerancija ±%2 za „%1” dovodi ga do %3, van dozvoljenih vrednosti.</translation>
    </message>
    <message>
        <source>At most %1 tolerances can be given.</source>
        <translation>Može se zadati najviše %1 tolerancija.</translation>
    </message>
    <message>
        <source>At a direct singularity the actuators do not hold the platform: the error from the tolerances is unbounded.</source>
        <translation>U singularitetu direktne kinematike aktuatori ne drže platformu: greška od tolerancija je neograničena.</translation>
    </message>
    <message>
        <source>At a combined singularity the error from the tolerances is undefined.</source>
        <translation>U kombinovanom singularitetu greška od tolerancija nije definisana.</translation>
    </message>
    <message>
        <source>The perturbed designs do not assemble at these inputs: the error from the tolerances is undefined here.</source>
        <translation>Izmenjene konstrukcije se ne sklapaju pri ovim ulazima: greška od tolerancija ovde nije definisana.</translation>
    </message>
    <message>
        <source>The requirement &apos;%1&apos; cannot be checked: this design declares no actuators.</source>
        <translation>Zahtev „%1“ ne može da se proveri: ova konstrukcija ne zadaje pogone.</translation>
    </message>
    <message>
        <source>The requirement &apos;%1&apos; has no comparison: write it as NAME&gt;=VALUE or NAME&lt;=VALUE, for example force_worst&gt;=50.</source>
        <translation>Zahtev „%1“ nema poređenje: napišite ga kao IME&gt;=VREDNOST ili IME&lt;=VREDNOST, na primer force_worst&gt;=50.</translation>
    </message>
    <message>
        <source>The requirement &apos;%1&apos; names no single capability value; it may name %2.</source>
        <translation>Zahtev „%1“ ne imenuje nijednu pojedinačnu vrednost mogućnosti pogona; može da imenuje %2.</translation>
    </message>
    <message>
        <source>The requirement &apos;%1&apos; does not end in a finite number.</source>
        <translation>Zahtev „%1“ se ne završava konačnim brojem.</translation>
    </message>
    <message>
        <source>worst-case error from the tolerances</source>
        <translation>najveća greška od tolerancija</translation>
    </message>
    <message>
        <source>near an inverse singularity: an actuator moves the platform less than 1/1000 of what it does at the home pose</source>
        <translation>blizu singulariteta inverzne kinematike: pogon pomera platformu manje od 1/1000 onoga što čini u početnom položaju</translation>
    </message>
    <message>
        <source>near a direct singularity: an actuator moves the platform more than 1000 times what it does at the home pose</source>
        <translation>blizu singulariteta direktne kinematike: pogon pomera platformu više od 1000 puta više nego u početnom položaju</translation>
    </message>
    <message>
        <source>near a combined singularity: one actuator moves the platform less than 1/1000, another more than 1000 times what it does at the home pose</source>
        <translation>blizu kombinovanog singulariteta: jedan pogon pomera platformu manje od 1/1000, drugi više od 1000 puta više nego u početnom položaju</translation>
    </message>
    <message>
        <source>mm³</source>
        <translation>mm³</translation>
    </message>
    <message>
        <source>mm³/rad</source>
        <translation>mm³/rad</translation>
    </message>
    <message>
        <source>mm⁴/rad</source>
        <translation>mm⁴/rad</translation>
    </message>
    <message>
        <source>mm⁵/rad</source>
        <translation>mm⁵/rad</translation>
    </message>
    <message>
        <source>mm⁴/rad²</source>
        <translation>mm⁴/rad²</translation>
    </message>
    <message>
        <source>mm⁵/rad²</source>
        <translation>mm⁵/rad²</translation>
    </message>
    <message>
        <source>mm⁶/rad²</source>
        <translation>mm⁶/rad²</translation>
    </message>
    <message>
        <source>mm⁶/rad³</source>
        <translation>mm⁶/rad³</translation>
    </message>
    <message>
        <source>mm⁷/rad³</source>
        <translation>mm⁷/rad³</translation>
    </message>
    <message>
        <source>C cannot reach %1 in this assembly mode (%2): it would cross the line BD, where the distal links are in line (a direct singularity); switch to the other assembly mode to go on.</source>
        <translation>C ne može da stigne do tačke %1 u ovom načinu sklapanja (%2): prešla bi pravu BD, na kojoj su spojke na istoj pravoj (singularitet direktne kinematike); pređite na drugi način sklapanja da biste nastavili.</translation>
    </message>
    <message>
        <source>The numbers put in are rounded as shown; every result is worked out from the unrounded values, so the last digits of a result can differ from one worked out by hand from the shown numbers.</source>
        <translation>Uvršteni brojevi su zaokruženi kao što su prikazani; svaki rezultat je izračunat iz nezaokruženih vrednosti, pa se poslednje cifre rezultata mogu razlikovati od onih koje se dobiju ručno iz prikazanih brojeva.</translation>
    </message>
    <message>
        <source>constant orientation</source>
        <translation>stalna orijentacija</translation>
    </message>
    <message>
        <source>free body</source>
        <translation>slobodno telo</translation>
    </message>
    <message>
        <source>°/s</source>
        <translation>°/s</translation>
    </message>
    <message>
        <source>platform: 2 DOF as a point or with constant orientation, 3 as a free body</source>
        <translation>platforma: 2 stepena slobode kao tačka ili sa stalnom orijentacijom, 3 kao slobodno telo</translation>
    </message>
    <message>
        <source>leg 1: type (the actuated joint underlined)</source>
        <translation>noga 1: tip (pogonski zglob podvučen)</translation>
    </message>
    <message>
        <source>leg 2: type (the actuated joint underlined)</source>
        <translation>noga 2: tip (pogonski zglob podvučen)</translation>
    </message>
    <message>
        <source>leg 3: type (the actuated joint underlined)</source>
        <translation>noga 3: tip (pogonski zglob podvučen)</translation>
    </message>
    <message>
        <source>At these inputs the platform would have left its assembly mode: it ends on the way, where it meets another at a direct singularity. Switch the assembly mode to go on.</source>
        <translation>Pri ovim ulazima platforma bi napustila svoj način sklapanja: on se završava na putu, gde se sreće sa drugim u singularitetu direktne kinematike. Da biste nastavili, promenite način sklapanja.</translation>
    </message>
    <message>
        <source>leg 1: working mode, the elbow left or right of A₁→P₁ (P̲RR: left, the root q = B + √…)</source>
        <translation>noga 1: radni režim, lakat levo ili desno od A₁→P₁ (P̲RR: levo — koren q = B + √…)</translation>
    </message>
    <message>
        <source>leg 2: working mode, the elbow left or right of A₂→P₂ (P̲RR: left, the root q = B + √…)</source>
        <translation>noga 2: radni režim, lakat levo ili desno od A₂→P₂ (P̲RR: levo — koren q = B + √…)</translation>
    </message>
    <message>
        <source>leg 3: working mode, the elbow left or right of A₃→P₃ (P̲RR: left, the root q = B + √…)</source>
        <translation>noga 3: radni režim, lakat levo ili desno od A₃→P₃ (P̲RR: levo — koren q = B + √…)</translation>
    </message>
    <message>
        <source>Jacobian, its own determinant (one input, one output)</source>
        <translation>Jakobijan, ujedno svoja determinanta (jedan ulaz, jedan izlaz)</translation>
    </message>
    <message>
        <source>J maps the rocker&apos;s rate onto the crank&apos;s, α̇ = J·δ̇, so J = 1/i₃₁.</source>
        <translation>J preslikava brzinu klackalice u brzinu poluge, α̇ = J·δ̇, pa je J = 1/i₃₁.</translation>
    </message>
    <message>
        <source>behind</source>
        <translation>iza</translation>
    </message>
    <message>
        <source>ahead</source>
        <translation>ispred</translation>
    </message>
    <message>
        <source>working mode of leg 1: the platform behind slider Z₁ along guide 1 or ahead of it</source>
        <translation>radni režim noge 1: platforma iza klizača Z₁ duž vođice 1 ili ispred njega</translation>
    </message>
    <message>
        <source>working mode of leg 2: the platform behind slider Z₂ along guide 2 or ahead of it</source>
        <translation>radni režim noge 2: platforma iza klizača Z₂ duž vođice 2 ili ispred njega</translation>
    </message>
    <message>
        <source>assembly mode: the platform left or right of Z₁→Z₂</source>
        <translation>način sklapanja: platforma levo ili desno od Z₁→Z₂</translation>
    </message>
    <message>
        <source>u₁ = x − s/2 − x_AB and u₂ = x + s/2 − x_CD are the rods&apos; runs along the guides, w and −w in the O form, −w and w in the X form.</source>
        <translation>u₁ = x − s/2 − x_AB i u₂ = x + s/2 − x_CD su projekcije šipki duž vođica: w i −w u obliku O, −w i w u obliku X.</translation>
    </message>
    <message>
        <source>Jacobian J = ∂d/∂θ</source>
        <translation>Jakobijan J = ∂d/∂θ</translation>
    </message>
    <message>
        <source>Output speed at the diagonal&apos;s top speed</source>
        <translation>Izlazna brzina pri najvećoj brzini dijagonale</translation>
    </message>
    <message>
        <source>Derivative of J, for the diagonal&apos;s acceleration</source>
        <translation>Izvod J, za ubrzanje dijagonale</translation>
    </message>
    <message>
        <source>J_i is the П-joint&apos;s Jacobian ∂d/∂θ of a П̲RR leg and 1 for the other leg types; C_i is A_i for an RP̲R leg.</source>
        <translation>J_i je jakobijan P-zgloba ∂d/∂θ za nogu P̲RR i 1 za noge drugih tipova; C_i je A_i za nogu RP̲R.</translation>
    </message>
    <message>
        <source>C_i is the centre of leg i&apos;s circle: the elbow, the slider joint, or A_i for an RP̲R leg.</source>
        <translation>C_i je središte kružnice noge i: lakat, zglob klizača ili A_i za nogu RP̲R.</translation>
    </message>
</context>
<context>
    <name>pkm::Animation</name>
    <message>
        <source>The animation needs a pose variable of the mechanism.</source>
        <translation>Za animaciju je potrebna promenljiva položaja mehanizma.</translation>
    </message>
    <message>
        <source>An animation has %1 to %2 frames, not %3.</source>
        <translation>Animacija mora imati od %1 do %2 kadrova, a ne %3.</translation>
    </message>
    <message>
        <source>Frame %1 (%2 = %3): %4</source>
        <translation>Kadar %1 (%2 = %3): %4</translation>
    </message>
    <message>
        <source>The animation was cancelled.</source>
        <translation>Animacija je otkazana.</translation>
    </message>
    <message>
        <source>A video file&apos;s name ends in .mp4 or .webm: %1.</source>
        <translation>Ime video-datoteke se završava na .mp4 ili .webm: %1.</translation>
    </message>
    <message>
        <source>An animation draws at most %1 million pixels (frames × width × height); %2 frames of %3 × %4 would be %5 million: take fewer steps or a smaller size.</source>
        <translation>Animacija crta najviše %1 miliona piksela (kadrovi × širina × visina); %2 kadrova veličine %3 × %4 bilo bi %5 miliona: uzmite manje koraka ili manju veličinu.</translation>
    </message>
</context>
<context>
    <name>pkm::AnimationDialog</name>
    <message>
        <source>Beside the view</source>
        <translation>Pored prikaza</translation>
    </message>
    <message>
        <source>Each frame shows the mechanism at the left and this plot at the right, its cursor following the pose.</source>
        <translation>Svaki kadar prikazuje mehanizam levo i ovaj dijagram desno; kursor dijagrama prati položaj.</translation>
    </message>
    <message>
        <source>Nothing</source>
        <translation>Ništa</translation>
    </message>
    <message>
        <source>The plot on screen: %1</source>
        <translation>Dijagram na ekranu: %1</translation>
    </message>
    <message>
        <source>%1 against %2 — %3</source>
        <translation>%1 od %2 — %3</translation>
    </message>
    <message>
        <source>Export Animation</source>
        <translation>Izvoz animacije</translation>
    </message>
    <message>
        <source>Move</source>
        <translation>Promenljiva</translation>
    </message>
    <message>
        <source>From</source>
        <translation>Od</translation>
    </message>
    <message>
        <source>To</source>
        <translation>Do</translation>
    </message>
    <message>
        <source>Frames</source>
        <translation>Broj kadrova</translation>
    </message>
    <message>
        <source> ms per frame</source>
        <translation> ms po kadru</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Brzina</translation>
    </message>
    <message>
        <source>%1 × %2 pixels</source>
        <translation>%1 × %2 piksela</translation>
    </message>
    <message>
        <source>Size</source>
        <translation>Veličina</translation>
    </message>
    <message>
        <source>Play back to the start (a smooth loop)</source>
        <translation>Vraćanje na početak (glatka petlja)</translation>
    </message>
    <message>
        <source>Export…</source>
        <translation>Izvezi…</translation>
    </message>
    <message numerus="yes">
        <source>Drawing %n frame(s)…</source>
        <translation>
            <numerusform>Crtanje %n kadra…</numerusform>
            <numerusform>Crtanje %n kadra…</numerusform>
            <numerusform>Crtanje %n kadrova…</numerusform>
        </translation>
    </message>
    <message>
        <source>Cannot write %1: %2.</source>
        <translation>Nije moguće upisati %1: %2.</translation>
    </message>
    <message>
        <source>Animation export cancelled.</source>
        <translation>Izvoz animacije je otkazan.</translation>
    </message>
    <message>
        <source>Wrote %1 (%2 kB)</source>
        <translation>Upisano %1 (%2 kB)</translation>
    </message>
    <message>
        <source>Animated GIF</source>
        <translation>Animirani GIF</translation>
    </message>
    <message>
        <source>MP4 video (H.264, 30 frames/s)</source>
        <translation>MP4 video (H.264, 30 kadrova/s)</translation>
    </message>
    <message>
        <source>WebM video (VP9, 30 frames/s)</source>
        <translation>WebM video (VP9, 30 kadrova/s)</translation>
    </message>
    <message>
        <source>Format</source>
        <translation>Format</translation>
    </message>
    <message>
        <source>A GIF&apos;s speed; a video plays 30 frames per second.</source>
        <translation>Brzina GIF-a; video se pušta sa 30 kadrova u sekundi.</translation>
    </message>
    <message>
        <source>Animated GIF (*.gif)</source>
        <translation>Animirani GIF (*.gif)</translation>
    </message>
    <message>
        <source>MP4 video (*.mp4)</source>
        <translation>MP4 video (*.mp4)</translation>
    </message>
    <message>
        <source>WebM video (*.webm)</source>
        <translation>WebM video (*.webm)</translation>
    </message>
    <message numerus="yes">
        <source>Encoding %n frame(s)…</source>
        <translation>
            <numerusform>Kodiranje %n kadra…</numerusform>
            <numerusform>Kodiranje %n kadra…</numerusform>
            <numerusform>Kodiranje %n kadrova…</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>pkm::AnimationPlot</name>
    <message>
        <source>%1 against %2</source>
        <translation>%1 (na apscisi: %2)</translation>
    </message>
    <message>
        <source>— (undefined at this singular pose)</source>
        <translation>— (nije definisano u ovom singularnom položaju)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a quantity the %2 can plot; it has %3</source>
        <translation>„%1” nije veličina koju %2 može da prikaže; postoje: %3</translation>
    </message>
</context>
<context>
    <name>pkm::BackgroundTask</name>
    <message>
        <source>Cancel</source>
        <translation>Otkaži</translation>
    </message>
</context>
<context>
    <name>pkm::DesignPanel</name>
    <message>
        <source>Geometry</source>
        <translation>Geometrija</translation>
    </message>
    <message>
        <source>Motion range</source>
        <translation>Opseg kretanja</translation>
    </message>
    <message>
        <source>Actuator</source>
        <translation>Aktuator</translation>
    </message>
    <message>
        <source>Motor body (drawing)</source>
        <translation>Kućište motora (crtež)</translation>
    </message>
    <message>
        <source>Modes</source>
        <translation>Režimi</translation>
    </message>
    <message>
        <source>less</source>
        <translation>manje</translation>
    </message>
    <message>
        <source>more…</source>
        <translation>više…</translation>
    </message>
    <message>
        <source>greater than %1</source>
        <translation>veće od %1</translation>
    </message>
    <message>
        <source>between %1 and %2</source>
        <translation>između %1 i %2</translation>
    </message>
    <message>
        <source>The last valid design is kept.</source>
        <translation>Zadržava se poslednja ispravna konstrukcija.</translation>
    </message>
    <message>
        <source>%1 (%2): &apos;%3&apos; is not a number.</source>
        <translation>%1 (%2): „%3“ nije broj.</translation>
    </message>
    <message>
        <source>%1: %2. Up/Down or the mouse wheel step by %3.</source>
        <translation>%1: %2. Tasteri ↑/↓ ili točkić miša menjaju vrednost u koracima od %3.</translation>
    </message>
    <message>
        <source>Name in design files and on the command line: %1</source>
        <translation>Ime u datotekama konstrukcija i u komandnoj liniji: %1</translation>
    </message>
</context>
<context>
    <name>pkm::DesignSession</name>
    <message>
        <source>Untitled design</source>
        <translation>Konstrukcija bez naziva</translation>
    </message>
    <message>
        <source>Cannot write %1: %2.</source>
        <translation>Nije moguće upisati %1: %2.</translation>
    </message>
</context>
<context>
    <name>pkm::Document</name>
    <message>
        <source>Open %1</source>
        <translation>Otvori %1</translation>
    </message>
    <message>
        <source>Switch to %1</source>
        <translation>Prelaz: %1</translation>
    </message>
    <message>
        <source>%1 stops at its upper limit %2: %3.</source>
        <translation>%1 se zaustavlja na gornjoj granici %2: %3.</translation>
    </message>
    <message>
        <source>%1 stops at its lower limit %2: %3.</source>
        <translation>%1 se zaustavlja na donjoj granici %2: %3.</translation>
    </message>
    <message>
        <source>%1 stops at its upper limit %2 (design range).</source>
        <translation>%1 se zaustavlja na gornjoj granici %2 (projektovani opseg).</translation>
    </message>
    <message>
        <source>%1 stops at its lower limit %2 (design range).</source>
        <translation>%1 se zaustavlja na donjoj granici %2 (projektovani opseg).</translation>
    </message>
    <message>
        <source>Close to a singular pose: small input steps make large output jumps.</source>
        <translation>Blizu singularnog položaja: mali koraci na ulazu daju velike skokove na izlazu.</translation>
    </message>
    <message>
        <source>That mode is not available at this pose.</source>
        <translation>Taj režim nije dostupan u ovom položaju.</translation>
    </message>
    <message>
        <source>Singular pose (inverse): the mechanism cannot be driven here.</source>
        <translation>Singularan položaj (inverzne kinematike): mehanizmom se ovde ne može upravljati.</translation>
    </message>
    <message>
        <source>Singular pose (direct): the mechanism cannot be driven here.</source>
        <translation>Singularan položaj (direktne kinematike): mehanizmom se ovde ne može upravljati.</translation>
    </message>
    <message>
        <source>Singular pose (combined): the mechanism cannot be driven here.</source>
        <translation>Singularan položaj (kombinovani): mehanizmom se ovde ne može upravljati.</translation>
    </message>
    <message>
        <source>A design keeps at most %1 bookmarks: remove one first.</source>
        <translation>Konstrukcija čuva najviše %1 obeleživača: prvo uklonite jedan.</translation>
    </message>
    <message>
        <source>Add bookmark “%1”</source>
        <translation>Dodaj obeleživač „%1”</translation>
    </message>
    <message>
        <source>There is no bookmark %1.</source>
        <translation>Nema obeleživača %1.</translation>
    </message>
    <message>
        <source>Remove bookmark “%1”</source>
        <translation>Ukloni obeleživač „%1”</translation>
    </message>
    <message>
        <source>Bookmark “%1”: %2</source>
        <translation>Obeleživač „%1”: %2</translation>
    </message>
    <message>
        <source>New design from template %1</source>
        <translation>Nova konstrukcija iz šablona %1</translation>
    </message>
    <message>
        <source>Move %1</source>
        <translation>Pomeri %1</translation>
    </message>
    <message>
        <source>A design keeps at most %1 tolerances.</source>
        <translation>Konstrukcija čuva najviše %1 tolerancija.</translation>
    </message>
    <message>
        <source>Change tolerance of %1</source>
        <translation>Izmeni toleranciju za %1</translation>
    </message>
    <message>
        <source>Clear tolerances</source>
        <translation>Ukloni tolerancije</translation>
    </message>
    <message>
        <source>Change requirements</source>
        <translation>Izmeni zahteve</translation>
    </message>
</context>
<context>
    <name>pkm::EquationsPanel</name>
    <message>
        <source>This kind lists no equations.</source>
        <translation>Za ovu vrstu mehanizma jednačine nisu navedene.</translation>
    </message>
</context>
<context>
    <name>pkm::FormWorkspaceView</name>
    <message>
        <source>x (mm)</source>
        <translation>x (mm)</translation>
    </message>
    <message>
        <source>y (mm)</source>
        <translation>y (mm)</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>union, outlined: %1</source>
        <translation>unija (kontura): %1</translation>
    </message>
    <message>
        <source>Areas of the forms: exact (closed form). Union: counted on a %1 × %2 grid.</source>
        <translation>Površine oblika: tačne (po formulama). Unija: prebrojana na mreži %1 × %2.</translation>
    </message>
    <message>
        <source>Areas counted on a %1 × %2 grid.</source>
        <translation>Površine prebrojane na mreži %1 × %2.</translation>
    </message>
</context>
<context>
    <name>pkm::FourBarPanel</name>
    <message>
        <source>Link lengths</source>
        <translation>Dužine članova</translation>
    </message>
    <message>
        <source>AB crank</source>
        <translation>AB poluga</translation>
    </message>
    <message>
        <source>BC coupler</source>
        <translation>BC spojka</translation>
    </message>
    <message>
        <source>CD rocker</source>
        <translation>CD klackalica</translation>
    </message>
    <message>
        <source>AD ground</source>
        <translation>AD postolje</translation>
    </message>
    <message>
        <source>Transmission angle γ at C</source>
        <translation>Ugao prenosa γ u C</translation>
    </message>
    <message>
        <source>The crank drives the rocker well when γ stays between %1° and %2°.</source>
        <translation>Poluga dobro pokreće klackalicu dok je γ između %1° i %2°.</translation>
    </message>
    <message>
        <source>The last valid design is kept.</source>
        <translation>Zadržava se poslednja ispravna konstrukcija.</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>the crank AB, the shortest link, turns fully; the rocker CD swings.</source>
        <translation>poluga AB, najkraći član, okreće se punim krugom; klackalica CD osciluje.</translation>
    </message>
    <message>
        <source>the rocker CD, the shortest link, could turn fully; the crank AB only swings.</source>
        <translation>klackalica CD, najkraći član, mogla bi da se okreće punim krugom; poluga AB samo osciluje.</translation>
    </message>
    <message>
        <source>the ground AD is the shortest link: the crank and the rocker both turn fully (drag link).</source>
        <translation>postolje AD je najkraći član: i poluga i klackalica okreću se punim krugom (dvostruka poluga).</translation>
    </message>
    <message>
        <source>the coupler BC is the shortest link: the crank and the rocker only swing.</source>
        <translation>spojka BC je najkraći član: poluga i klackalica samo osciluju.</translation>
    </message>
    <message>
        <source>non-Grashof: no link turns fully.</source>
        <translation>Grashofov uslov nije ispunjen: nijedan član se ne okreće punim krugom.</translation>
    </message>
    <message>
        <source>the links can fold flat in line, where the open and crossed branches meet.</source>
        <translation>članovi mogu da se slože u jednu liniju, gde se susreću otvorena i ukrštena grana.</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;: s + l = %2 %3 p + q = %4; %5</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;: s + l = %2 %3 p + q = %4; %5</translation>
    </message>
    <message>
        <source>&lt;b&gt;α&lt;/b&gt;: the crank turns fully, %1 … %2</source>
        <translation>&lt;b&gt;α&lt;/b&gt;: poluga se okreće punim krugom, %1 … %2</translation>
    </message>
    <message>
        <source>&lt;b&gt;α&lt;/b&gt; assembles from %1 to %2 only: at the ends the coupler and the rocker are in line (dead points)</source>
        <translation>&lt;b&gt;α&lt;/b&gt;: mehanizam se može sklopiti samo od %1 do %2; na krajevima su spojka i klackalica u istoj liniji (mrtve tačke)</translation>
    </message>
    <message>
        <source>&lt;span style=&apos;color:#b3261e&apos;&gt;over the motion %1° … %2°: enters the poor band&lt;/span&gt;</source>
        <translation>&lt;span style=&apos;color:#b3261e&apos;&gt;tokom kretanja %1° … %2°: ulazi u zonu lošeg prenosa&lt;/span&gt;</translation>
    </message>
    <message>
        <source>over the motion %1° … %2°: inside %3° … %4°</source>
        <translation>tokom kretanja %1° … %2°: unutar %3° … %4°</translation>
    </message>
    <message>
        <source>%1 — poor: %2</source>
        <translation>%1 — loš prenos: %2</translation>
    </message>
    <message>
        <source>below %1°</source>
        <translation>ispod %1°</translation>
    </message>
    <message>
        <source>above %1°</source>
        <translation>iznad %1°</translation>
    </message>
    <message>
        <source>α stops at its upper limit: %1.</source>
        <translation>α se zaustavlja na gornjoj granici: %1.</translation>
    </message>
    <message>
        <source>α stops at its lower limit: %1.</source>
        <translation>α se zaustavlja na donjoj granici: %1.</translation>
    </message>
    <message>
        <source>Crank-rocker</source>
        <translation>Mehanizam poluga–klackalica</translation>
    </message>
    <message>
        <source>Rocker-crank</source>
        <translation>Mehanizam klackalica–poluga</translation>
    </message>
    <message>
        <source>Double-crank</source>
        <translation>Dvostruka poluga</translation>
    </message>
    <message>
        <source>Double-rocker</source>
        <translation>Dvostruka klackalica</translation>
    </message>
    <message>
        <source>Triple-rocker</source>
        <translation>Trostruka klackalica</translation>
    </message>
    <message>
        <source>Change-point</source>
        <translation>Granični Grashofov slučaj</translation>
    </message>
    <message>
        <source>%1. &lt;b&gt;δ&lt;/b&gt; swings over %2 … %3 (crossed branch).</source>
        <translation>%1. &lt;b&gt;δ&lt;/b&gt; se menja u opsegu %2 … %3 (ukrštena grana).</translation>
    </message>
    <message>
        <source>%1. &lt;b&gt;δ&lt;/b&gt; swings over %2 … %3 (open branch).</source>
        <translation>%1. &lt;b&gt;δ&lt;/b&gt; se menja u opsegu %2 … %3 (otvorena grana).</translation>
    </message>
</context>
<context>
    <name>pkm::FourBarPlots</name>
    <message>
        <source>δ(α) — fig. 4</source>
        <translation>δ(α) — sl. 4</translation>
    </message>
    <message>
        <source>ω₃, ε₃ — fig. 6</source>
        <translation>ω₃, ε₃ — sl. 6</translation>
    </message>
    <message>
        <source>δ vs AB — fig. 5</source>
        <translation>δ od AB — sl. 5</translation>
    </message>
    <message>
        <source>The rocker angle δ over the crank&apos;s range (click to set α)</source>
        <translation>Ugao klackalice δ u celom opsegu poluge (klikom se zadaje α)</translation>
    </message>
    <message>
        <source>The rocker&apos;s angular velocity and acceleration at constant ω₁ (click to set α)</source>
        <translation>Ugaona brzina i ugaono ubrzanje klackalice pri stalnoj ω₁ (klikom se zadaje α)</translation>
    </message>
    <message>
        <source>The transmission angle at C; shaded where the crank drives the rocker poorly</source>
        <translation>Ugao prenosa u zglobu C; osenčeno je tamo gde poluga loše pokreće klackalicu</translation>
    </message>
    <message>
        <source>δ at the current α as the crank length AB changes, the other links fixed</source>
        <translation>δ pri trenutnom α u zavisnosti od dužine poluge AB, ostali članovi nepromenjeni</translation>
    </message>
    <message>
        <source>Click or drag to set the crank angle α</source>
        <translation>Kliknite ili prevucite da zadate ugao poluge α</translation>
    </message>
    <message>
        <source>AB/BC/CD/AD = %1/%2/%3/%4 mm, %5 branch</source>
        <translation>AB/BC/CD/AD = %1/%2/%3/%4 mm, %5 grana</translation>
    </message>
    <message>
        <source>Fig. 4 — rocker angle δ(α)</source>
        <translation>Sl. 4 — ugao klackalice δ(α)</translation>
    </message>
    <message>
        <source>Fig. 6 — rocker angular velocity ω₃ = dδ/dt</source>
        <translation>Sl. 6 — ugaona brzina klackalice ω₃ = dδ/dt</translation>
    </message>
    <message>
        <source>Fig. 6 — rocker angular acceleration ε₃ = d²δ/dt²</source>
        <translation>Sl. 6 — ugaono ubrzanje klackalice ε₃ = d²δ/dt²</translation>
    </message>
    <message>
        <source>Transmission angle γ(α), (5)</source>
        <translation>Ugao prenosa γ(α), (5)</translation>
    </message>
    <message>
        <source>Fig. 5 — rocker angle δ against the crank length AB</source>
        <translation>Sl. 5 — ugao klackalice δ u zavisnosti od dužine poluge AB</translation>
    </message>
    <message>
        <source>ω₁ = %1 rad/s constant; exact (the document&apos;s (8) has the opposite sign)</source>
        <translation>ω₁ = %1 rad/s = const; tačno (formula (8) iz rada ima suprotan znak)</translation>
    </message>
    <message>
        <source>ω₁ = %1 rad/s constant; exact (not the document&apos;s (14))</source>
        <translation>ω₁ = %1 rad/s = const; tačno (ne po formuli (14) iz rada)</translation>
    </message>
    <message>
        <source>at α = %1°; BC, CD, AD fixed</source>
        <translation>pri α = %1°; BC, CD, AD nepromenjeni</translation>
    </message>
    <message>
        <source>ω₃ (rad/s)</source>
        <translation>ω₃ (rad/s)</translation>
    </message>
    <message>
        <source>ε₃ (rad/s²)</source>
        <translation>ε₃ (rad/s²)</translation>
    </message>
    <message>
        <source>crank length AB (mm)</source>
        <translation>dužina poluge AB (mm)</translation>
    </message>
    <message>
        <source>crank angle α (°)</source>
        <translation>ugao poluge α (°)</translation>
    </message>
    <message>
        <source>poor transmission: |γ| &lt; %1° or &gt; %2°</source>
        <translation>loš prenos: |γ| &lt; %1° ili &gt; %2°</translation>
    </message>
    <message>
        <source>δ at α = %1°</source>
        <translation>δ pri α = %1°</translation>
    </message>
    <message>
        <source>largest AB that assembles: %1 mm</source>
        <translation>najveća AB koja se može sklopiti: %1 mm</translation>
    </message>
    <message>
        <source>ω₃ = %1 rad/s</source>
        <translation>ω₃ = %1 rad/s</translation>
    </message>
    <message>
        <source>ε₃ = %1 rad/s²</source>
        <translation>ε₃ = %1 rad/s²</translation>
    </message>
    <message>
        <source>AB = %1 mm, δ = %2°</source>
        <translation>AB = %1 mm, δ = %2°</translation>
    </message>
    <message>
        <source>%1 → %2∞: dead point</source>
        <translation>%1 → %2∞: mrtva tačka</translation>
    </message>
    <message>
        <source>no pose</source>
        <translation>nema položaja</translation>
    </message>
    <message>
        <source>crossed</source>
        <comment>branch</comment>
        <translation>ukrštena</translation>
    </message>
    <message>
        <source>open</source>
        <comment>branch</comment>
        <translation>otvorena</translation>
    </message>
</context>
<context>
    <name>pkm::GifWriter</name>
    <message>
        <source>An animation needs at least one frame.</source>
        <translation>Animaciji je potreban bar jedan kadar.</translation>
    </message>
    <message>
        <source>A GIF frame must be 1 to 65535 pixels on each side.</source>
        <translation>GIF kadar mora imati od 1 do 65535 piksela po svakoj stranici.</translation>
    </message>
    <message>
        <source>All frames of a GIF must have the same size.</source>
        <translation>Svi kadrovi GIF-a moraju biti iste veličine.</translation>
    </message>
    <message>
        <source>giflib: out of memory.</source>
        <translation>giflib: nema dovoljno memorije.</translation>
    </message>
    <message>
        <source>giflib could not reduce a frame to 256 colours.</source>
        <translation>giflib nije uspeo da svede kadar na 256 boja.</translation>
    </message>
</context>
<context>
    <name>pkm::GuideWindow</name>
    <message>
        <source>PKM Studio User Guide</source>
        <translation>Uputstvo za PKM Studio</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Nazad</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Na početak</translation>
    </message>
    <message>
        <source>The start of the guide</source>
        <translation>Početak uputstva</translation>
    </message>
    <message>
        <source>&amp;Find:</source>
        <translation>&amp;Pronađi:</translation>
    </message>
    <message>
        <source>a word in the guide (Ctrl+F)</source>
        <translation>reč u uputstvu (Ctrl+F)</translation>
    </message>
    <message>
        <source>Previous</source>
        <translation>Prethodno</translation>
    </message>
    <message>
        <source>Next</source>
        <translation>Sledeće</translation>
    </message>
    <message>
        <source>Not found</source>
        <translation>Nije pronađeno</translation>
    </message>
</context>
<context>
    <name>pkm::LinkageView</name>
    <message>
        <source>Click to switch to: %1</source>
        <translation>Kliknite da prebacite: %1</translation>
    </message>
    <message>
        <source>this pose</source>
        <translation>ovaj položaj</translation>
    </message>
</context>
<context>
    <name>pkm::LinkageView3D</name>
    <message>
        <source>3D view unavailable: OpenGL 3.3 could not be started.</source>
        <translation>3D prikaz nije dostupan: OpenGL 3.3 nije mogao da se pokrene.</translation>
    </message>
    <message>
        <source>A picture needs a size of at least one pixel.</source>
        <translation>Slika mora biti velika bar jedan piksel.</translation>
    </message>
</context>
<context>
    <name>pkm::MainWindow</name>
    <message>
        <source>2D</source>
        <translation>2D</translation>
    </message>
    <message>
        <source>3D</source>
        <translation>3D</translation>
    </message>
    <message>
        <source>The mechanism in 3D: drag to turn it, right-drag to pan, wheel to zoom</source>
        <translation>Mehanizam u 3D: prevucite da ga okrenete, desnim tasterom da ga pomerite, točkićem za uvećanje</translation>
    </message>
    <message>
        <source>Design</source>
        <translation>Konstrukcija</translation>
    </message>
    <message>
        <source>Mobility</source>
        <translation>Pokretljivost</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datoteka</translation>
    </message>
    <message>
        <source>&amp;Open Design…</source>
        <translation>&amp;Otvori konstrukciju…</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>Otvori &amp;skorašnje</translation>
    </message>
    <message>
        <source>&amp;Save Design</source>
        <translation>&amp;Sačuvaj konstrukciju</translation>
    </message>
    <message>
        <source>Save Design &amp;As…</source>
        <translation>Sačuvaj konstrukciju &amp;kao…</translation>
    </message>
    <message>
        <source>Export &amp;Drawing (DXF)…</source>
        <translation>Izvezi &amp;crtež (DXF)…</translation>
    </message>
    <message>
        <source>Export &amp;Parameter Sheet…</source>
        <translation>Izvezi &amp;listu parametara…</translation>
    </message>
    <message>
        <source>Save 2D &amp;View Picture…</source>
        <translation>Sačuvaj sliku &amp;2D prikaza…</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Izlaz</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Uređivanje</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Opozovi</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Ponovi</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Opozovi</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Ponovi</translation>
    </message>
    <message>
        <source>&amp;Presets</source>
        <translation>&amp;Primeri</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Prikaz</translation>
    </message>
    <message>
        <source>&amp;Fit Mechanism</source>
        <translation>&amp;Uklopi mehanizam</translation>
    </message>
    <message>
        <source>Zoom &amp;In</source>
        <translation>&amp;Uvećaj</translation>
    </message>
    <message>
        <source>Zoom &amp;Out</source>
        <translation>&amp;Umanji</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Pomoć</translation>
    </message>
    <message>
        <source>&amp;About PKM Studio</source>
        <translation>&amp;O programu PKM Studio</translation>
    </message>
    <message>
        <source>Switched to %1.</source>
        <translation>Prelazak na: %1.</translation>
    </message>
    <message>
        <source>Open Design</source>
        <translation>Otvaranje konstrukcije</translation>
    </message>
    <message>
        <source>PKM Studio designs (*.pkm.json);;All files (*)</source>
        <translation>Konstrukcije PKM Studio (*.pkm.json);;Sve datoteke (*)</translation>
    </message>
    <message>
        <source>Save Design</source>
        <translation>Čuvanje konstrukcije</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>Sačuvano: %1</translation>
    </message>
    <message>
        <source>Save Design As</source>
        <translation>Čuvanje konstrukcije kao</translation>
    </message>
    <message>
        <source>PKM Studio designs (*.pkm.json)</source>
        <translation>Konstrukcije PKM Studio (*.pkm.json)</translation>
    </message>
    <message>
        <source>Unsaved Changes</source>
        <translation>Nesačuvane izmene</translation>
    </message>
    <message>
        <source>The design “%1” has changes that are not saved. Save them?</source>
        <translation>Konstrukcija „%1“ ima nesačuvane izmene. Da li da ih sačuvam?</translation>
    </message>
    <message>
        <source>Recover Design</source>
        <translation>Vraćanje konstrukcije</translation>
    </message>
    <message>
        <source>PKM Studio closed unexpectedly while “%1” had unsaved changes (autosaved %2). Recover them?</source>
        <translation>PKM Studio se neočekivano zatvorio dok je „%1“ imala nesačuvane izmene (automatski sačuvano %2). Da li da ih vratim?</translation>
    </message>
    <message>
        <source>Recovered “%1”: save it to keep the changes.</source>
        <translation>Vraćeno „%1“: sačuvajte da biste zadržali izmene.</translation>
    </message>
    <message>
        <source>%1[*] — PKM Studio</source>
        <translation>%1[*] — PKM Studio</translation>
    </message>
    <message>
        <source>%1 no longer exists; removed from the recent files.</source>
        <translation>%1 više ne postoji; uklonjena je sa spiska skorašnjih datoteka.</translation>
    </message>
    <message>
        <source>About PKM Studio</source>
        <translation>O programu PKM Studio</translation>
    </message>
    <message>
        <source>&lt;h3&gt;PKM Studio %1&lt;/h3&gt;&lt;p&gt;Design, analysis and teaching of parallel-kinematic mechanisms.&lt;/p&gt;&lt;p&gt;Licensed under the GNU General Public License, version 3 or later.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;PKM Studio %1&lt;/h3&gt;&lt;p&gt;Projektovanje, analiza i nastava mehanizama paralelne kinematike.&lt;/p&gt;&lt;p&gt;Licenca: GNU General Public License, verzija 3 ili novija.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Export Drawing (DXF)</source>
        <translation>Izvoz crteža (DXF)</translation>
    </message>
    <message>
        <source>DXF drawings (*.dxf);;All files (*)</source>
        <translation>DXF crteži (*.dxf);;Sve datoteke (*)</translation>
    </message>
    <message>
        <source>Cannot write the drawing to %1: %2.</source>
        <translation>Crtež nije moguće upisati u %1: %2.</translation>
    </message>
    <message>
        <source>Wrote the drawing to %1 (DXF R12, mm).</source>
        <translation>Crtež je upisan u %1 (DXF R12, mm).</translation>
    </message>
    <message>
        <source>Export Parameter Sheet</source>
        <translation>Izvoz liste parametara</translation>
    </message>
    <message>
        <source>PDF parameter sheets (*.pdf);;JSON (*.json);;CSV (*.csv)</source>
        <translation>Liste parametara PDF (*.pdf);;JSON (*.json);;CSV (*.csv)</translation>
    </message>
    <message>
        <source>Computing the parameter sheet…</source>
        <translation>Računam listu parametara…</translation>
    </message>
    <message>
        <source>Wrote the parameter sheet to %1.</source>
        <translation>Lista parametara je upisana u %1.</translation>
    </message>
    <message>
        <source>Wrote the 2D view to %1.</source>
        <translation>2D prikaz je upisan u %1.</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Jezik</translation>
    </message>
    <message>
        <source>Main Toolbar</source>
        <translation>Glavna traka alata</translation>
    </message>
    <message>
        <source>The language “%1” is not available.</source>
        <translation>Jezik „%1“ nije dostupan.</translation>
    </message>
    <message>
        <source>&amp;Source Documents…</source>
        <translation>&amp;Izvorni dokumenti…</translation>
    </message>
    <message>
        <source>Source Documents</source>
        <translation>Izvorni dokumenti</translation>
    </message>
    <message>
        <source>&lt;p&gt;PKM Studio models the mechanisms of these four documents: the active П-joint (1), MOMA (2), the O-X glide (3), the four-bar and the mobility formulas (4). Where a printed formula or number is wrong, the program uses the corrected one; the README&apos;s section on the mathematics lists each correction.&lt;/p&gt;%1</source>
        <translation>&lt;p&gt;PKM Studio modelira mehanizme ova četiri dokumenta: aktivni P-zglob (1), MOMA (2), O-X glide (3), zglobni četvorougao i formule pokretljivosti (4). Gde je štampana formula ili broj pogrešan, program koristi ispravljeni; odeljak README-a o matematici navodi svako ispravljanje.&lt;/p&gt;%1</translation>
    </message>
    <message>
        <source>Play Toolbar</source>
        <translation>Traka za pokretanje</translation>
    </message>
    <message>
        <source>Play / &amp;Pause</source>
        <translation>Pokreni / &amp;pauza</translation>
    </message>
    <message>
        <source>Move the chosen joint variable by itself, or stop it</source>
        <translation>Pokreće izabranu promenljivu zgloba samu od sebe ili je zaustavlja</translation>
    </message>
    <message>
        <source>&amp;Bookmarks</source>
        <translation>&amp;Obeleživači</translation>
    </message>
    <message>
        <source>&amp;Add Bookmark</source>
        <translation>&amp;Dodaj obeleživač</translation>
    </message>
    <message>
        <source>Keep this pose to come back to it (saved with the design)</source>
        <translation>Zapamti ovaj položaj da mu se vratiš (čuva se uz konstrukciju)</translation>
    </message>
    <message>
        <source>&amp;Previous Bookmark</source>
        <translation>&amp;Prethodni obeleživač</translation>
    </message>
    <message>
        <source>&amp;Next Bookmark</source>
        <translation>&amp;Sledeći obeleživač</translation>
    </message>
    <message>
        <source>&amp;Remove Current Bookmark</source>
        <translation>&amp;Ukloni trenutni obeleživač</translation>
    </message>
    <message>
        <source>Bookmark %1 kept: %2</source>
        <translation>Obeleživač %1 zapamćen: %2</translation>
    </message>
    <message>
        <source>Bookmark %1 of %2: %3</source>
        <translation>Obeleživač %1 od %2: %3</translation>
    </message>
    <message>
        <source>No bookmarks yet: Bookmarks ▸ Add Bookmark (Ctrl+B) keeps the pose shown.</source>
        <translation>Još nema obeleživača: Obeleživači ▸ Dodaj obeleživač (Ctrl+B) pamti prikazani položaj.</translation>
    </message>
    <message>
        <source>&amp;Presentation Mode</source>
        <translation>Režim &amp;prezentacije</translation>
    </message>
    <message>
        <source>Full screen, large text, high contrast: the linkage, its plot and the sliders (F5; Esc leaves)</source>
        <translation>Ceo ekran, krupan tekst, visok kontrast: mehanizam, njegov dijagram i klizači (F5; izlaz Esc)</translation>
    </message>
    <message>
        <source>&amp;Text Size</source>
        <translation>Veličina &amp;teksta</translation>
    </message>
    <message>
        <source>Presentation mode: Esc or F5 leaves it; Page Up and Page Down step through the bookmarks.</source>
        <translation>Režim prezentacije: izlaz Esc ili F5; Page Up i Page Down listaju obeleživače.</translation>
    </message>
    <message>
        <source>Equations</source>
        <translation>Jednačine</translation>
    </message>
    <message>
        <source>New from &amp;Template</source>
        <translation>Novo iz &amp;šablona</translation>
    </message>
    <message>
        <source>Export &amp;Animation (GIF, MP4, WebM)…</source>
        <translation>Izvezi &amp;animaciju (GIF, MP4, WebM)…</translation>
    </message>
    <message>
        <source>5R (two driven cranks)</source>
        <translation>5R (dve pogonske poluge)</translation>
    </message>
    <message>
        <source>5R driven by two П-joints</source>
        <translation>5R s pogonom od dva P-zgloba</translation>
    </message>
    <message>
        <source>Constant orientation, 2 DOF, with two П-joints</source>
        <translation>Stalna orijentacija, 2 stepena slobode, sa dva P-zgloba</translation>
    </message>
    <message>
        <source>3-RP̲R (three struts)</source>
        <translation>3-RP̲R (tri teleskopska štapa)</translation>
    </message>
    <message>
        <source>3-R̲RR (three driven cranks)</source>
        <translation>3-R̲RR (tri pogonske poluge)</translation>
    </message>
    <message>
        <source>3-P̲RR (three driven sliders)</source>
        <translation>3-P̲RR (tri pogonska klizača)</translation>
    </message>
    <message>
        <source>2-P̲RR (two driven sliders, MOMA 3a)</source>
        <translation>2-P̲RR (dva pogonska klizača, MOMA 3a)</translation>
    </message>
    <message>
        <source>&amp;User Guide</source>
        <translation>&amp;Uputstvo</translation>
    </message>
    <message>
        <source>What&apos;s &amp;This?</source>
        <translation>Šta je &amp;ovo?</translation>
    </message>
    <message>
        <source>The plots of this mechanism over the range of its input; the cursor marks the current pose. A right click saves a plot as a picture.</source>
        <translation>Grafici ovog mehanizma po opsegu njegovog ulaza; kursor označava trenutni položaj. Klik desnim tasterom čuva grafik kao sliku.</translation>
    </message>
    <message>
        <source>The workspace map: where the platform can go, coloured by the quantity chosen above it, with the singular curves. Click a point to move the platform there; the marker shows the current pose.</source>
        <translation>Mapa radnog prostora: gde platforma može da stigne, obojena po veličini izabranoj iznad nje, sa singularnim krivama. Klik na tačku pomera platformu tamo; oznaka pokazuje trenutni položaj.</translation>
    </message>
    <message>
        <source>The linkage at its current pose. Drag a round handle to move a joint or the platform; the wheel zooms, the right button pans and F fits the mechanism. Faint ghosts are the other assembly modes: click one to switch to it. Limits and singular poses are told at the bottom.</source>
        <translation>Mehanizam u trenutnom položaju. Prevucite okruglu ručicu da pomerite zglob ili platformu; točkić uvećava, desni taster pomera pogled, a F uklapa mehanizam. Blede senke su drugi načini sklapanja: klik na jednu prelazi na nju. O granicama i singularnim položajima se obaveštava dole.</translation>
    </message>
    <message>
        <source>The joint variables: each slider and its number set one variable of the mechanism, and the pose follows at once. A value the mechanism cannot reach is refused with a message.</source>
        <translation>Unutrašnje koordinate: svaki klizač i njegov broj zadaju jednu koordinatu mehanizma, a položaj odmah sledi. Vrednost koju mehanizam ne može da dostigne odbija se porukom.</translation>
    </message>
    <message>
        <source>Play moves the chosen joint variable by itself over the range set here, at this speed, in a loop, forth and back or once. It stops at a limit or before a singular pose and says why.</source>
        <translation>Pokretanje samo pomera izabranu koordinatu po ovde zadatom opsegu, ovom brzinom: u krug, napred i nazad ili jednom. Zaustavlja se na granici ili pre singularnog položaja i kaže zašto.</translation>
    </message>
    <message>
        <source>The design: every dimension and mode of the mechanism. Change a value and the linkage, the values, the plots and the maps follow; every change can be undone (Ctrl+Z).</source>
        <translation>Konstrukcija: sve mere i režimi mehanizma. Promenite vrednost i šema, vrednosti, grafici i mape će je pratiti; svaka izmena može da se opozove (Ctrl+Z).</translation>
    </message>
    <message>
        <source>The values at this pose: joint variables, the Jacobian, its determinant and condition number and what the actuators deliver, each with its unit and meaning. At a singular pose a value that is infinite reads ∞ and one that is undefined reads —.</source>
        <translation>Vrednosti u ovom položaju: koordinate, jakobijan, njegova determinanta i broj uslovljenosti i ono što daju aktuatori, svaka sa jedinicom i značenjem. U singularnom položaju beskonačna vrednost se prikazuje kao ∞, a neodređena kao —.</translation>
    </message>
    <message>
        <source>The mobility of the mechanism: its degrees of freedom counted by the structural formulas and by the rank of its loop equations at this pose, and where the formulas are wrong.</source>
        <translation>Pokretljivost mehanizma: broj stepeni slobode po strukturnim formulama i po rangu jednačina zatvorenih kontura u ovom položaju, i gde formule greše.</translation>
    </message>
    <message>
        <source>The governing equations of this mechanism with the source document&apos;s equation numbers, each followed by the same equation with the current numbers put in; they follow the pose.</source>
        <translation>Osnovne jednačine ovog mehanizma sa brojevima jednačina izvornog dokumenta, a posle svake ista jednačina sa upisanim trenutnim brojevima; prate položaj.</translation>
    </message>
    <message>
        <source>The mechanism in 3D at the current pose: drag to turn it, right-drag to pan, the wheel zooms and a double-click fits it. The sliders drive it as they drive the 2D view.</source>
        <translation>Mehanizam u 3D u trenutnom položaju: prevlačenje ga okreće, prevlačenje desnim tasterom pomera, točkić uvećava, a dvostruki klik uklapa. Klizači ga pokreću kao i pogled 2D.</translation>
    </message>
    <message>
        <source>The assembly and working modes: the mode of the current pose, and a button for each other mode the mechanism can take here, which switches to it.</source>
        <translation>Načini sklapanja i radni režimi: režim trenutnog položaja i dugme za svaki drugi režim koji mehanizam ovde može da zauzme; ono prelazi na njega.</translation>
    </message>
    <message>
        <source>Ellipses</source>
        <translation>Elipse</translation>
    </message>
    <message>
        <source>Velocity and force polygons and ellipses at the platform point (V)</source>
        <translation>Poligoni i elipse brzine i sile u tački platforme (V)</translation>
    </message>
    <message>
        <source>&amp;Velocity and Force Shapes</source>
        <translation>Oblici &amp;brzine i sile</translation>
    </message>
    <message>
        <source>The velocity and force polygons (solid) and ellipses (dashed) the actuators give at the platform point, to the scale of the legend (V)</source>
        <translation>Poligoni (pune linije) i elipse (isprekidane) brzine i sile koje aktuatori daju u tački platforme, u razmeri legende (V)</translation>
    </message>
    <message>
        <source>This design states no actuator limits, so there are no velocity and force shapes to draw.</source>
        <translation>Ova konstrukcija ne zadaje granice aktuatora, pa nema oblika brzine i sile za crtanje.</translation>
    </message>
    <message>
        <source>The velocity and force shapes cannot be scaled for this design: its home pose is singular.</source>
        <translation>Oblici brzine i sile ne mogu se srazmeriti za ovu konstrukciju: njen početni položaj je singularan.</translation>
    </message>
    <message>
        <source>Tolerances</source>
        <translation>Tolerancije</translation>
    </message>
    <message>
        <source>What the actuators must deliver at the platform; the workspace map shows where it holds</source>
        <translation>Šta pogoni moraju da daju na platformi; mapa radnog prostora pokazuje gde je to ispunjeno</translation>
    </message>
    <message>
        <source>The requirements are kept with the design; this mechanism has no workspace map to show where they hold.</source>
        <translation>Zahtevi su sačuvani uz konstrukciju; ovaj mehanizam nema mapu radnog prostora koja bi pokazala gde su ispunjeni.</translation>
    </message>
    <message>
        <source>Re&amp;quirements…</source>
        <translation>&amp;Zahtevi…</translation>
    </message>
    <message>
        <source>Presentation P&amp;lot</source>
        <translation>Gra&amp;fikon prezentacije</translation>
    </message>
    <message>
        <source>Values</source>
        <translation>Vrednosti</translation>
    </message>
    <message>
        <source>The output of this mechanism is one angle: its speed, torque and stiffness are in “Values”; there is no platform point to draw shapes at.</source>
        <translation>Izlaz ovog mehanizma je jedan ugao: njegova brzina, moment i krutost su u „Vrednostima”; nema tačke platforme na kojoj bi se crtali oblici.</translation>
    </message>
</context>
<context>
    <name>pkm::MobilityPanel</name>
    <message>
        <source>✓ right</source>
        <translation>✓ tačno</translation>
    </message>
    <message>
        <source>⚠ wrong</source>
        <translation>⚠ netačno</translation>
    </message>
    <message numerus="yes">
        <source>W = %1, but the rank gives M = %2: the formula counts %3 equations per loop, and %n of them are redundant.</source>
        <translation>
            <numerusform>W = %1, ali rang daje M = %2: formula uzima %3 kao broj jednačina po konturi, a %n od njih je suvišna.</numerusform>
            <numerusform>W = %1, ali rang daje M = %2: formula uzima %3 kao broj jednačina po konturi, a %n od njih su suvišne.</numerusform>
            <numerusform>W = %1, ali rang daje M = %2: formula uzima %3 kao broj jednačina po konturi, a %n od njih je suvišno.</numerusform>
        </translation>
    </message>
    <message>
        <source>A negative W rightly says “rigid”, but it is not the mobility: M = 0.</source>
        <translation>Negativno W s pravom kaže „krut“, ali to nije pokretljivost: M = 0.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Classroom example: the spatial parallelogram.&lt;/b&gt; The П-joint prototype&apos;s hinged parallelogram (a = 170 mm, b = 68 mm): four parallel revolute axes, counted as a spatial chain.</source>
        <translation>&lt;b&gt;Primer za nastavu: prostorni paralelogram.&lt;/b&gt; Zglobni paralelogram prototipa P-zgloba (a = 170 mm, b = 68 mm): četiri paralelne ose obrtnih parova, posmatrane kao prostorni lanac.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Classroom example: the Bennett linkage.&lt;/b&gt; Four skew revolute axes, opposite links equal (a = 100 mm, b ≈ 188 mm) with twists α = 30°, β = 70° and a/sin α = b/sin β.</source>
        <translation>&lt;b&gt;Primer za nastavu: Benetov mehanizam.&lt;/b&gt; Četiri mimoilazne ose obrtnih parova, naspramni članovi jednaki (a = 100 mm, b ≈ 188 mm), sa uglovima uvijanja α = 30°, β = 70° i a/sin α = b/sin β.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Classroom example: a general spatial 4R loop.&lt;/b&gt; Four revolute axes in general position, without Bennett&apos;s proportions: the same counts as the Bennett linkage.</source>
        <translation>&lt;b&gt;Primer za nastavu: opšta prostorna kontura 4R.&lt;/b&gt; Četiri ose obrtnih parova u opštem položaju, bez Benetovih proporcija: isto brojanje kao kod Benetovog mehanizma.</translation>
    </message>
    <message>
        <source>the %1</source>
        <translation>%1</translation>
    </message>
    <message>
        <source>the ground (%1)</source>
        <translation>postolje (%1)</translation>
    </message>
    <message numerus="yes">
        <source>&lt;b&gt;Links&lt;/b&gt;: %1 and %n moving link(s), n = %n: %2.</source>
        <translation>
            <numerusform>&lt;b&gt;Članovi&lt;/b&gt;: %1 i %n pokretni član, n = %n: %2.</numerusform>
            <numerusform>&lt;b&gt;Članovi&lt;/b&gt;: %1 i %n pokretna člana, n = %n: %2.</numerusform>
            <numerusform>&lt;b&gt;Članovi&lt;/b&gt;: %1 i %n pokretnih članova, n = %n: %2.</numerusform>
        </translation>
    </message>
    <message>
        <source>&lt;b&gt;Pairs&lt;/b&gt;: %1.</source>
        <translation>&lt;b&gt;Parovi&lt;/b&gt;: %1.</translation>
    </message>
    <message>
        <source>none</source>
        <translation>nema</translation>
    </message>
    <message>
        <source>Actuated: %1.</source>
        <translation>Pogonjeni: %1.</translation>
    </message>
    <message numerus="yes">
        <source>&lt;b&gt;Loops&lt;/b&gt;: %n independent loop(s), L = %n.</source>
        <translation>
            <numerusform>&lt;b&gt;Konture&lt;/b&gt;: %n nezavisna kontura, L = %n.</numerusform>
            <numerusform>&lt;b&gt;Konture&lt;/b&gt;: %n nezavisne konture, L = %n.</numerusform>
            <numerusform>&lt;b&gt;Konture&lt;/b&gt;: %n nezavisnih kontura, L = %n.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>&lt;b&gt;Idle freedoms&lt;/b&gt;: %n (a part spinning about its own axis), counted in every number below.</source>
        <translation>
            <numerusform>&lt;b&gt;Pasivni stepeni slobode&lt;/b&gt;: %n (deo koji se okreće oko sopstvene ose); uračunati u svaki broj ispod.</numerusform>
            <numerusform>&lt;b&gt;Pasivni stepeni slobode&lt;/b&gt;: %n (deo koji se okreće oko sopstvene ose); uračunati u svaki broj ispod.</numerusform>
            <numerusform>&lt;b&gt;Pasivni stepeni slobode&lt;/b&gt;: %n (deo koji se okreće oko sopstvene ose); uračunati u svaki broj ispod.</numerusform>
        </translation>
    </message>
    <message>
        <source>At this pose the mechanism gains an instantaneous freedom (singularity).</source>
        <translation>U ovom položaju mehanizam dobija trenutni stepen slobode (singularitet).</translation>
    </message>
    <message>
        <source>The rank of the loop equations drops from %1 to %2: the instantaneous mobility is %3, the mobility next to this pose %4.</source>
        <translation>Rang jednačina zatvaranja pada sa %1 na %2: trenutna pokretljivost je %3, pokretljivost u blizini ovog položaja %4.</translation>
    </message>
    <message>
        <source>With the actuators locked the mechanism can still move instantaneously here: it gains a freedom the actuators do not control (a direct singularity).</source>
        <translation>Sa zakočenim pogonima mehanizam ovde i dalje može trenutno da se pomeri: dobija stepen slobode koji pogoni ne kontrolišu (singularitet direktne kinematike).</translation>
    </message>
    <message>
        <source>⚠ Singular pose</source>
        <translation>⚠ Singularan položaj</translation>
    </message>
    <message>
        <source>Chebyshev (planar chains)</source>
        <translation>Čebišev (ravanski lanci)</translation>
    </message>
    <message>
        <source>Does not apply: the chain has pairs that do not move in its plane.</source>
        <translation>Ne primenjuje se: lanac ima parove koji se ne kreću u njegovoj ravni.</translation>
    </message>
    <message>
        <source>Does not apply: a spatial chain.</source>
        <translation>Ne primenjuje se: prostorni lanac.</translation>
    </message>
    <message>
        <source>Somov–Malyshev (spatial chains)</source>
        <translation>Somov–Mališev (prostorni lanci)</translation>
    </message>
    <message>
        <source>The source document prints the last term as “+ P₁”: a typo. A pair of class 1 takes away one freedom, so − P₁.</source>
        <translation>Izvorni rad poslednji član štampa kao „+ P₁“: to je štamparska greška. Par klase 1 oduzima jedan stepen slobode, dakle − P₁.</translation>
    </message>
    <message>
        <source>⚠ Here it matters: with + P₁ the formula would give W = %1.</source>
        <translation>⚠ Ovde je to bitno: sa + P₁ formula bi dala W = %1.</translation>
    </message>
    <message>
        <source>No loop equation is redundant: the structural count holds.</source>
        <translation>Nijedna jednačina zatvaranja nije suvišna: strukturno brojanje važi.</translation>
    </message>
    <message>
        <source>Bennett&apos;s proportions (opposite links equal, a/sin α = b/sin β) make them depend on the others, so the linkage moves although the count says it cannot.</source>
        <translation>Benetove proporcije (naspramni članovi jednaki, a/sin α = b/sin β) čine ih zavisnim od ostalih, pa se mehanizam kreće iako brojanje kaže da ne može.</translation>
    </message>
    <message>
        <source>the joint axes are parallel, so each loop moves in a plane and imposes only 3 of its 6 equations.</source>
        <translation>ose zglobova su paralelne, pa se svaka kontura kreće u ravni i nameće samo 3 od svojih 6 jednačina.</translation>
    </message>
    <message>
        <source>%1 independent equations already hold all %1 freedoms of the pairs: a rigid chain with constraints to spare.</source>
        <translation>nezavisnih jednačina već ima %1 — one drže sve stepene slobode parova (F = %1): krut lanac sa suvišnim vezama.</translation>
    </message>
    <message>
        <source>the pairs&apos; axes lie in a special way (parallel, or meeting in a point), so some equations repeat others: an overconstrained chain.</source>
        <translation>ose parova leže na poseban način (paralelne su ili se seku u jednoj tački), pa neke jednačine ponavljaju druge: lanac sa suvišnim vezama.</translation>
    </message>
    <message numerus="yes">
        <source>%n redundant loop equation(s): %1</source>
        <translation>
            <numerusform>%n suvišna jednačina zatvaranja: %1</numerusform>
            <numerusform>%n suvišne jednačine zatvaranja: %1</numerusform>
            <numerusform>%n suvišnih jednačina zatvaranja: %1</numerusform>
        </translation>
    </message>
    <message>
        <source>From the rank of the constraint Jacobian</source>
        <translation>Iz ranga Jakobijeve matrice veza</translation>
    </message>
    <message numerus="yes">
        <source>An open chain, no loop: nothing holds the %n freedom(s) of its pairs, M = F = %n.</source>
        <translation>
            <numerusform>Otvoren lanac, bez kontura: ništa ne ograničava %n stepen slobode njegovih parova, M = F = %n.</numerusform>
            <numerusform>Otvoren lanac, bez kontura: ništa ne ograničava %n stepena slobode njegovih parova, M = F = %n.</numerusform>
            <numerusform>Otvoren lanac, bez kontura: ništa ne ograničava %n stepeni slobode njegovih parova, M = F = %n.</numerusform>
        </translation>
    </message>
    <message>
        <source>F = %1 freedoms of the pairs; 6L = %2 loop equations.</source>
        <translation>F = %1 — broj stepeni slobode parova; 6L = %2 — broj jednačina zatvaranja.</translation>
    </message>
    <message>
        <source>At this pose: rank %1 of %2 → %3 (instantaneous).</source>
        <translation>U ovom položaju: rang %1 od %2 → %3 (trenutna).</translation>
    </message>
    <message>
        <source>Next to it: rank %1 of %2 → %3.</source>
        <translation>U blizini: rang %1 od %2 → %3.</translation>
    </message>
    <message>
        <source>rank %1 of %2 loop equations → %3</source>
        <translation>rang %1 od %2 jednačina zatvaranja → %3</translation>
    </message>
    <message>
        <source>Mobility M = %1</source>
        <translation>Pokretljivost M = %1</translation>
    </message>
    <message>
        <source>(%1 at this pose)</source>
        <translation>(%1 u ovom položaju)</translation>
    </message>
    <message>
        <source>Actuation</source>
        <translation>Pogoni</translation>
    </message>
    <message numerus="yes">
        <source>%n actuated freedom(s)</source>
        <translation>
            <numerusform>%n pogonjen stepen slobode</numerusform>
            <numerusform>%n pogonjena stepena slobode</numerusform>
            <numerusform>%n pogonjenih stepeni slobode</numerusform>
        </translation>
    </message>
    <message>
        <source>No pair is actuated.</source>
        <translation>Nijedan par nije pogonjen.</translation>
    </message>
    <message>
        <source>⚠ Under-actuated by %1:</source>
        <translation>⚠ Nedostaje pogona (%1):</translation>
    </message>
    <message numerus="yes">
        <source>%1 for mobility %2; with the actuators locked, it keeps %n freedom(s).</source>
        <translation>
            <numerusform>%1 za pokretljivost %2; sa zakočenim pogonima zadržava %n stepen slobode.</numerusform>
            <numerusform>%1 za pokretljivost %2; sa zakočenim pogonima zadržava %n stepena slobode.</numerusform>
            <numerusform>%1 za pokretljivost %2; sa zakočenim pogonima zadržava %n stepeni slobode.</numerusform>
        </translation>
    </message>
    <message>
        <source>Redundantly actuated: %1 for mobility %2.</source>
        <translation>Suvišan broj pogona: %1 za pokretljivost %2.</translation>
    </message>
    <message>
        <source>✓ Fully actuated:</source>
        <translation>✓ Potpuno pogonjen:</translation>
    </message>
    <message>
        <source>%1 for mobility %2.</source>
        <translation>%1 za pokretljivost %2.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Verdict&lt;/b&gt;: %1</source>
        <translation>&lt;b&gt;Zaključak&lt;/b&gt;: %1</translation>
    </message>
    <message>
        <source>Analyse:</source>
        <translation>Analiza:</translation>
    </message>
    <message>
        <source>This mechanism</source>
        <translation>Ovaj mehanizam</translation>
    </message>
    <message>
        <source>Example: spatial parallelogram</source>
        <translation>Primer: prostorni paralelogram</translation>
    </message>
    <message>
        <source>Example: Bennett linkage</source>
        <translation>Primer: Benetov mehanizam</translation>
    </message>
    <message>
        <source>Example: general spatial 4R (rigid)</source>
        <translation>Primer: opšti prostorni 4R (krut)</translation>
    </message>
    <message>
        <source>Classroom examples: chains where the structural formulas fail, and one where the counts predict the truth</source>
        <translation>Primeri za nastavu: lanci za koje strukturne formule greše i jedan za koji brojanje daje tačan odgovor</translation>
    </message>
    <message>
        <source>No mechanism to analyse.</source>
        <translation>Nema mehanizma za analizu.</translation>
    </message>
    <message>
        <source>Analysing…</source>
        <translation>Analiziram…</translation>
    </message>
    <message numerus="yes">
        <source>%n revolute</source>
        <translation>
            <numerusform>%n obrtni</numerusform>
            <numerusform>%n obrtna</numerusform>
            <numerusform>%n obrtnih</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n prismatic</source>
        <translation>
            <numerusform>%n prizmatični</numerusform>
            <numerusform>%n prizmatična</numerusform>
            <numerusform>%n prizmatičnih</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n screw</source>
        <translation>
            <numerusform>%n zavojni</numerusform>
            <numerusform>%n zavojna</numerusform>
            <numerusform>%n zavojnih</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n cylindrical</source>
        <translation>
            <numerusform>%n cilindrični</numerusform>
            <numerusform>%n cilindrična</numerusform>
            <numerusform>%n cilindričnih</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n planar cam</source>
        <translation>
            <numerusform>%n ravanski bregasti</numerusform>
            <numerusform>%n ravanska bregasta</numerusform>
            <numerusform>%n ravanskih bregastih</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n spherical</source>
        <translation>
            <numerusform>%n sferni</numerusform>
            <numerusform>%n sferna</numerusform>
            <numerusform>%n sfernih</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>At this pose the mechanism gains %n instantaneous freedoms (singularity).</source>
        <translation>
            <numerusform>U ovom položaju mehanizam dobija %n trenutni stepen slobode (singularitet).</numerusform>
            <numerusform>U ovom položaju mehanizam dobija %n trenutna stepena slobode (singularitet).</numerusform>
            <numerusform>U ovom položaju mehanizam dobija %n trenutnih stepeni slobode (singularitet).</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>pkm::ModeBar</name>
    <message>
        <source>Modes: %1</source>
        <translation>Režimi: %1</translation>
    </message>
    <message>
        <source>→ %1:</source>
        <extracomment>groups of mode buttons named by numbers: &quot;→ assembly mode:&quot; [1] [2] …, &quot;→ other working mode, leg:&quot; [1] [2]</extracomment>
        <translation>→ %1:</translation>
    </message>
    <message>
        <source>→ %1</source>
        <translation>→ %1</translation>
    </message>
    <message>
        <source>Switch to %1. The mechanism stays in its mode until you click here or on its ghost in the view.</source>
        <translation>Prebaci: %1. Mehanizam ostaje u trenutnom režimu dok ne kliknete ovde ili na njegov providni obris u prikazu.</translation>
    </message>
    <message>
        <source>→ %1, %2:</source>
        <translation>→ %1, %2:</translation>
    </message>
    <message>
        <source>The mode the mechanism is in.</source>
        <translation>Režim u kome je mehanizam.</translation>
    </message>
</context>
<context>
    <name>pkm::OxGlidePanel</name>
    <message>
        <source>Form:</source>
        <translation>Oblik:</translation>
    </message>
    <message>
        <source>O — extended</source>
        <translation>O — opruženi</translation>
    </message>
    <message>
        <source>X — crossed</source>
        <translation>X — ukršteni</translation>
    </message>
    <message>
        <source>Work in the extended form: the rods splay outwards from the platform.</source>
        <translation>Rad u opruženom obliku: štapovi se od platforme šire ka spolja.</translation>
    </message>
    <message>
        <source>Work in the crossed form: the slider pairs pass each other and the rods cross.</source>
        <translation>Rad u ukrštenom obliku: parovi klizača se mimoilaze, a štapovi se ukrštaju.</translation>
    </message>
    <message>
        <source>Animate crossing</source>
        <translation>Animiraj prelaz</translation>
    </message>
    <message>
        <source>Raise the platform towards the O↔X crossing (y = l, x_CD − x_AB = s) and stop short of the singular pose there.</source>
        <translation>Podiže platformu ka prelazu O↔X (y = l, x_CD − x_AB = s) i zaustavlja se pre singularnog položaja.</translation>
    </message>
    <message>
        <source>Workspace O / X</source>
        <translation>Radni prostor O / X</translation>
    </message>
    <message>
        <source>Singularity map</source>
        <translation>Mapa singulariteta</translation>
    </message>
    <message>
        <source>The crossing stopped: the design changed.</source>
        <translation>Prelaz je zaustavljen: konstrukcija je promenjena.</translation>
    </message>
    <message>
        <source>Workspaces of the O and X forms (fig. 5)</source>
        <translation>Radni prostori oblika O i X (sl. 5)</translation>
    </message>
    <message>
        <source>O↔X crossing y = l: singular</source>
        <translation>Prelaz O↔X y = l: singularitet</translation>
    </message>
    <message>
        <source>The crossing stopped: the pose was moved.</source>
        <translation>Prelaz je zaustavljen: položaj je pomeren.</translation>
    </message>
    <message>
        <source>Crossing stopped.</source>
        <translation>Prelaz je zaustavljen.</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Zaustavi</translation>
    </message>
    <message>
        <source>Raising the platform towards the O↔X crossing at y = l…</source>
        <translation>Platforma se podiže ka prelazu O↔X na y = l…</translation>
    </message>
    <message>
        <source>&lt;b&gt;Stopped %1 short of the singular pose.&lt;/b&gt; At y = l = %2 the slider pairs stand at x_CD − x_AB = s: the rods are perpendicular to the guides and parallel to each other, so the platform can swing sideways while the sliders hold still (a combined singularity), and it may leave in either form. Here the rods are at %3° to the guides. Passing needs the platform guided through that point: choose the form to leave in.</source>
        <translation>&lt;b&gt;Zaustavljeno %1 pre singularnog položaja.&lt;/b&gt; Na y = l = %2 parovi klizača stoje na x_CD − x_AB = s: štapovi su upravni na vođice i paralelni međusobno, pa platforma može da se njiše u stranu dok klizači miruju (kombinovani singularitet) i da izađe u bilo kom obliku. Ovde su štapovi pod uglom od %3° prema vođicama. Za prolaz platforma mora biti vođena kroz tu tačku: izaberite oblik u kome će izaći.</translation>
    </message>
    <message>
        <source>The crossing stopped %1 below y = l, short of the singular pose x_CD − x_AB = s.</source>
        <translation>Prelaz je zaustavljen %1 ispod y = l, pre singularnog položaja x_CD − x_AB = s.</translation>
    </message>
    <message>
        <source>Leave in the extended (O) form</source>
        <translation>Izađi u opruženom obliku (O)</translation>
    </message>
    <message>
        <source>Leave in the crossed (X) form</source>
        <translation>Izađi u ukrštenom obliku (X)</translation>
    </message>
    <message>
        <source>Go back in the crossed (X) form</source>
        <translation>Vrati se u ukrštenom obliku (X)</translation>
    </message>
    <message>
        <source>Go back in the extended (O) form</source>
        <translation>Vrati se u opruženom obliku (O)</translation>
    </message>
    <message>
        <source>Switched to the crossed (X) form at the same platform position.</source>
        <translation>Prešlo se na ukršteni oblik (X) u istom položaju platforme.</translation>
    </message>
    <message>
        <source>Switched to the extended (O) form at the same platform position.</source>
        <translation>Prešlo se na opruženi oblik (O) u istom položaju platforme.</translation>
    </message>
    <message>
        <source>The crossed (X) form is not available at this pose.</source>
        <translation>Ukršteni oblik (X) nije dostupan u ovom položaju.</translation>
    </message>
    <message>
        <source>The extended (O) form is not available at this pose.</source>
        <translation>Opruženi oblik (O) nije dostupan u ovom položaju.</translation>
    </message>
    <message>
        <source>The platform is back at y = %1, in the crossed (X) form.</source>
        <translation>Platforma je vraćena na y = %1, u ukrštenom obliku (X).</translation>
    </message>
    <message>
        <source>The platform is back at y = %1, in the extended (O) form.</source>
        <translation>Platforma je vraćena na y = %1, u opruženom obliku (O).</translation>
    </message>
    <message>
        <source>Lowering the platform in the crossed (X) form…</source>
        <translation>Platforma se spušta u ukrštenom obliku (X)…</translation>
    </message>
    <message>
        <source>Lowering the platform in the extended (O) form…</source>
        <translation>Platforma se spušta u opruženom obliku (O)…</translation>
    </message>
</context>
<context>
    <name>pkm::PJointPlots</name>
    <message>
        <source>Geometry</source>
        <translation>Geometrija</translation>
    </message>
    <message>
        <source>Jacobian</source>
        <translation>Jakobijan</translation>
    </message>
    <message>
        <source>Actuator</source>
        <translation>Aktuator</translation>
    </message>
    <message>
        <source>Fig. 8 — diagonal length d(θ), (2)</source>
        <translation>Sl. 8 — dužina dijagonale d(θ), (2)</translation>
    </message>
    <message>
        <source>Fig. 9 — passive angle φ(θ)</source>
        <translation>Sl. 9 — pasivni ugao φ(θ)</translation>
    </message>
    <message>
        <source>Fig. 10 — transmission angle μ(θ)</source>
        <translation>Sl. 10 — ugao prenosa μ(θ)</translation>
    </message>
    <message>
        <source>Fig. 11 — Jacobian J(θ) = ∂d/∂θ, (7)</source>
        <translation>Sl. 11 — jakobijan J(θ) = ∂d/∂θ, (7)</translation>
    </message>
    <message>
        <source>Fig. 12 — inverse Jacobian J⁻¹(θ), (8)</source>
        <translation>Sl. 12 — inverzni jakobijan J⁻¹(θ), (8)</translation>
    </message>
    <message>
        <source>Fig. 15 — output resolution Δθ = Δd/J</source>
        <translation>Sl. 15 — rezolucija izlaza Δθ = Δd/J</translation>
    </message>
    <message>
        <source>Fig. 16 — output speed θ̇ = ḋ_max/J</source>
        <translation>Sl. 16 — brzina izlaza θ̇ = ḋ_max/J</translation>
    </message>
    <message>
        <source>Fig. 17 — output torque T = J·F_max, (13)</source>
        <translation>Sl. 17 — izlazni moment T = J·F_max, (13)</translation>
    </message>
    <message>
        <source>a = %1 mm, k = %2, θ %3°…%4°; family at the same a</source>
        <translation>a = %1 mm, k = %2, θ %3°…%4°; familija pri istom a</translation>
    </message>
    <message>
        <source>diagonal OA from the base OB</source>
        <translation>dijagonala OA u odnosu na osnovicu OB</translation>
    </message>
    <message>
        <source>at A, diagonal to crank; J = a·sin μ</source>
        <translation>u tački A, između dijagonale i poluge; J = a·sin μ</translation>
    </message>
    <message>
        <source>ḋ = J·θ̇; a = %1 mm, k = %2</source>
        <translation>ḋ = J·θ̇; a = %1 mm, k = %2</translation>
    </message>
    <message>
        <source>θ̇ = J⁻¹·ḋ; J⁻¹ → ∞ at θ = ±90°</source>
        <translation>θ̇ = J⁻¹·ḋ; J⁻¹ → ∞ pri θ = ±90°</translation>
    </message>
    <message>
        <source>one motor step Δd = %1 mm</source>
        <translation>jedan korak motora Δd = %1 mm</translation>
    </message>
    <message>
        <source>at the maximum linear speed ḋ_max = %1 mm/s</source>
        <translation>pri najvećoj linijskoj brzini ḋ_max = %1 mm/s</translation>
    </message>
    <message>
        <source>F_max = %1 N; motor torque T_M = %2 N·m at any θ (15)</source>
        <translation>F_max = %1 N; moment motora T_M = %2 N·m za svako θ (15)</translation>
    </message>
    <message>
        <source>θ (°)</source>
        <translation>θ (°)</translation>
    </message>
    <message>
        <source>dθ/dt</source>
        <translation>dθ/dt</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>this design (k = %1)</source>
        <translation>ova konstrukcija (k = %1)</translation>
    </message>
    <message>
        <source>beyond its θ range</source>
        <translation>izvan njenog opsega θ</translation>
    </message>
    <message>
        <source>k = %1</source>
        <translation>k = %1</translation>
    </message>
    <message>
        <source>recommended %1°…%2° (J ≥ %3 % of best)</source>
        <translation>preporučeno %1°…%2° (J ≥ %3 % od najboljeg)</translation>
    </message>
    <message>
        <source>steep region</source>
        <translation>strma oblast</translation>
    </message>
    <message>
        <source>μ &lt; %1°: force almost along the crank</source>
        <translation>μ &lt; %1°: sila deluje skoro duž poluge</translation>
    </message>
</context>
<context>
    <name>pkm::PictureDialog</name>
    <message>
        <source>PNG pictures (*.png)</source>
        <translation>PNG slike (*.png)</translation>
    </message>
    <message>
        <source>SVG drawings (*.svg)</source>
        <translation>SVG crteži (*.svg)</translation>
    </message>
    <message>
        <source>PDF documents (*.pdf)</source>
        <translation>PDF dokumenti (*.pdf)</translation>
    </message>
    <message>
        <source>%1 × %2 pixels is not a picture size: each side must be from %3 to %4.</source>
        <translation>%1 × %2 piksela nije veličina slike: svaka stranica mora biti od %3 do %4.</translation>
    </message>
    <message>
        <source>%1 dpi is not a resolution: it must be from %2 to %3 dpi.</source>
        <translation>%1 dpi nije rezolucija: mora biti od %2 do %3 dpi.</translation>
    </message>
    <message>
        <source>The %1 picture could not be drawn.</source>
        <translation>Slika %1 nije mogla da se nacrta.</translation>
    </message>
    <message>
        <source>There is not enough memory for a picture of %1 × %2 pixels.</source>
        <translation>Nema dovoljno memorije za sliku od %1 × %2 piksela.</translation>
    </message>
    <message>
        <source>Drawn by %1</source>
        <translation>Nacrtano u programu %1</translation>
    </message>
    <message>
        <source>“%1” is not a picture format: the file name must end in .png, .svg or .pdf.</source>
        <translation>„%1“ nije format slike: ime datoteke mora da se završava sa .png, .svg ili .pdf.</translation>
    </message>
    <message>
        <source>There is no plot to draw.</source>
        <translation>Nema grafikona za crtanje.</translation>
    </message>
    <message>
        <source>“%1” could not be opened for writing: %2.</source>
        <translation>„%1“ nije moguće otvoriti za upis: %2.</translation>
    </message>
    <message>
        <source>The picture could not be written to “%1”: %2.</source>
        <translation>Sliku nije moguće upisati u „%1“: %2.</translation>
    </message>
    <message>
        <source>“%1” could not be saved: %2.</source>
        <translation>„%1“ nije moguće sačuvati: %2.</translation>
    </message>
    <message>
        <source>Save picture…</source>
        <translation>Sačuvaj sliku…</translation>
    </message>
    <message>
        <source>Save this plot as a PNG picture, an SVG or a PDF drawing</source>
        <translation>Sačuvaj ovaj grafikon kao PNG sliku ili kao SVG ili PDF crtež</translation>
    </message>
    <message>
        <source>Save Picture</source>
        <translation>Čuvanje slike</translation>
    </message>
    <message>
        <source>Picture Size</source>
        <translation>Veličina slike</translation>
    </message>
    <message>
        <source>%1 × %2</source>
        <translation>%1 × %2</translation>
    </message>
    <message>
        <source>As shown — %1</source>
        <translation>Kao na ekranu — %1</translation>
    </message>
    <message>
        <source>Twice as shown — %1</source>
        <translation>Dvostruko veće — %1</translation>
    </message>
    <message>
        <source>Full HD — %1</source>
        <translation>Full HD — %1</translation>
    </message>
    <message>
        <source>4K UHD — %1</source>
        <translation>4K UHD — %1</translation>
    </message>
    <message>
        <source>Custom</source>
        <translation>Proizvoljna</translation>
    </message>
    <message>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <source>%1 dpi</source>
        <translation>%1 dpi</translation>
    </message>
    <message>
        <source>An SVG drawing is scalable: its size is in CSS pixels.</source>
        <translation>SVG crtež je skalabilan: veličina mu je u CSS pikselima.</translation>
    </message>
    <message>
        <source>The PDF&apos;s page is the size in pixels at this resolution.</source>
        <translation>Stranica PDF-a ima veličinu u pikselima pri ovoj rezoluciji.</translation>
    </message>
    <message>
        <source>Stored in the PNG: the size it prints at.</source>
        <translation>Upisuje se u PNG i određuje veličinu pri štampi.</translation>
    </message>
    <message>
        <source>&amp;Size:</source>
        <translation>&amp;Veličina:</translation>
    </message>
    <message>
        <source>&amp;Width:</source>
        <translation>&amp;Širina:</translation>
    </message>
    <message>
        <source>&amp;Height:</source>
        <translation>V&amp;isina:</translation>
    </message>
    <message>
        <source>&amp;Resolution:</source>
        <translation>&amp;Rezolucija:</translation>
    </message>
    <message>
        <source>%1 × %2 mm</source>
        <translation>%1 × %2 mm</translation>
    </message>
    <message>
        <source>%1 × %2 pixels</source>
        <translation>%1 × %2 piksela</translation>
    </message>
    <message>
        <source>An SVG drawing of %1 (CSS pixels), lines and text as vectors.</source>
        <translation>SVG crtež od %1 (CSS pikseli), linije i tekst kao vektori.</translation>
    </message>
    <message>
        <source>A PDF page of %1: %2 at %3 dpi, lines and text as vectors.</source>
        <translation>PDF stranica od %1: %2 pri %3 dpi, linije i tekst kao vektori.</translation>
    </message>
    <message>
        <source>A PNG picture of %1; it prints at %2 at %3 dpi.</source>
        <translation>PNG slika od %1; štampa se kao %2 pri %3 dpi.</translation>
    </message>
</context>
<context>
    <name>pkm::PlanarParallelPanel</name>
    <message>
        <source>Add leg 3</source>
        <translation>Dodaj nogu 3</translation>
    </message>
    <message>
        <source>Remove leg 3</source>
        <translation>Ukloni nogu 3</translation>
    </message>
    <message>
        <source>Change the platform</source>
        <translation>Promeni platformu</translation>
    </message>
    <message>
        <source>Change the type of leg %1</source>
        <translation>Promeni tip noge %1</translation>
    </message>
    <message>
        <source>Change the working mode of leg %1</source>
        <translation>Promeni radni režim noge %1</translation>
    </message>
    <message>
        <source>Legs</source>
        <translation>Noge</translation>
    </message>
    <message>
        <source>&amp;Platform:</source>
        <translation>&amp;Platforma:</translation>
    </message>
    <message>
        <source>Add leg</source>
        <translation>Dodaj nogu</translation>
    </message>
    <message>
        <source>A third leg, a strut opposite the other two: the platform becomes a free body (3 DOF).</source>
        <translation>Treća noga, štap naspram druge dve: platforma postaje slobodno telo (3 stepena slobode).</translation>
    </message>
    <message>
        <source>Two legs: the platform becomes a point, or keeps a constant orientation if both legs are P̲RR or П̲RR.</source>
        <translation>Dve noge: platforma postaje tačka, ili zadržava stalnu orijentaciju ako su obe noge P̲RR ili P̲RR.</translation>
    </message>
    <message>
        <source>a point (2 legs, x and y)</source>
        <translation>tačka (2 noge, x i y)</translation>
    </message>
    <message>
        <source>constant orientation (2 legs, x and y)</source>
        <translation>stalna orijentacija (2 noge, x i y)</translation>
    </message>
    <message>
        <source>free body (3 legs, x, y and φ)</source>
        <translation>slobodno telo (3 noge, x, y i φ)</translation>
    </message>
    <message>
        <source>Leg %1:</source>
        <translation>Noga %1:</translation>
    </message>
    <message>
        <source>R̲RR: driven crank and link</source>
        <translation>R̲RR: pogonska poluga i spojka</translation>
    </message>
    <message>
        <source>P̲RR: driven slider and link</source>
        <translation>P̲RR: pogonski klizač i spojka</translation>
    </message>
    <message>
        <source>RP̲R: telescopic strut</source>
        <translation>RP̲R: teleskopski štap</translation>
    </message>
    <message>
        <source>П̲RR: active П-joint and link</source>
        <translation>P̲RR: aktivni P-zglob i spojka</translation>
    </message>
    <message>
        <source>The leg&apos;s joints from the base, the actuated one underlined.</source>
        <translation>Zglobovi noge od osnove, pogonski podvučen.</translation>
    </message>
    <message>
        <source>working mode +1</source>
        <translation>radni režim +1</translation>
    </message>
    <message>
        <source>working mode −1</source>
        <translation>radni režim −1</translation>
    </message>
    <message>
        <source>+1: the elbow left of the line from A to the platform point (P̲RR: the slider beyond the foot of the perpendicular).</source>
        <translation>+1: lakat levo od linije od A do tačke platforme (P̲RR: klizač iza podnožja normale).</translation>
    </message>
    <message>
        <source>point</source>
        <translation>tačka</translation>
    </message>
    <message>
        <source>constant orientation</source>
        <translation>stalna orijentacija</translation>
    </message>
    <message>
        <source>free body</source>
        <translation>slobodno telo</translation>
    </message>
</context>
<context>
    <name>pkm::PlayBar</name>
    <message>
        <source>Pause</source>
        <translation>Pauza</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Pokreni</translation>
    </message>
    <message>
        <source>/s</source>
        <translation>/s</translation>
    </message>
    <message>
        <source>Play: move the chosen joint variable by itself (stops at a limit or before a singular pose)</source>
        <translation>Pokreni: izabrana promenljiva zgloba se kreće sama (zaustavlja se na granici ili pre singularnog položaja)</translation>
    </message>
    <message>
        <source>from</source>
        <translation>od</translation>
    </message>
    <message>
        <source>to</source>
        <translation>do</translation>
    </message>
    <message>
        <source>speed</source>
        <translation>brzina</translation>
    </message>
    <message>
        <source>Loop</source>
        <translation>U krug</translation>
    </message>
    <message>
        <source>Forth and back</source>
        <translation>Napred i nazad</translation>
    </message>
    <message>
        <source>Once</source>
        <translation>Jednom</translation>
    </message>
    <message>
        <source>At the end of the range: start again, turn back, or stop</source>
        <translation>Na kraju opsega: počni ponovo, vrati se ili stani</translation>
    </message>
</context>
<context>
    <name>pkm::Player</name>
    <message>
        <source>inverse</source>
        <translation>inverzne kinematike</translation>
    </message>
    <message>
        <source>direct</source>
        <translation>direktne kinematike</translation>
    </message>
    <message>
        <source>combined</source>
        <translation>kombinovani</translation>
    </message>
    <message>
        <source>Play needs a range: “from” must be below “to” for %1, and the speed above 0.</source>
        <translation>Za pokretanje je potreban opseg: za %1 „od” mora biti manje od „do”, a brzina veća od 0.</translation>
    </message>
    <message>
        <source>Play stopped before a singular pose (%1) at %2 = %3.</source>
        <translation>Pokretanje je zaustavljeno pre singularnog položaja (%1) pri %2 = %3.</translation>
    </message>
    <message>
        <source>Play reached the end of its range.</source>
        <translation>Pokretanje je stiglo do kraja opsega.</translation>
    </message>
    <message>
        <source>Play turned back: %1</source>
        <translation>Pokretanje se vratilo nazad: %1</translation>
    </message>
    <message>
        <source>Play stopped close to a singular pose at %1 = %2.</source>
        <translation>Pokretanje je zaustavljeno blizu singularnog položaja pri %1 = %2.</translation>
    </message>
    <message>
        <source>Play turned back close to a singular pose at %1 = %2.</source>
        <translation>Pokretanje se vratilo nazad blizu singularnog položaja pri %1 = %2.</translation>
    </message>
    <message>
        <source>Play turned back before a singular pose (%1) at %2 = %3.</source>
        <translation>Pokretanje se vratilo nazad pre singularnog položaja (%1) pri %2 = %3.</translation>
    </message>
</context>
<context>
    <name>pkm::Renderer3D</name>
    <message>
        <source>No OpenGL context is current.</source>
        <translation>Nema tekućeg OpenGL konteksta.</translation>
    </message>
    <message>
        <source>The driver offers OpenGL %1%2.%3; the 3D view needs OpenGL 3.3.</source>
        <translation>Drajver nudi OpenGL %1%2.%3, a 3D prikazu je potreban OpenGL 3.3.</translation>
    </message>
    <message>
        <source>The OpenGL 3.3 core functions could not be resolved.</source>
        <translation>Funkcije jezgra OpenGL 3.3 nisu mogle da se učitaju.</translation>
    </message>
    <message>
        <source>OpenGL %1.%2 (%3), %4</source>
        <translation>OpenGL %1.%2 (%3), %4</translation>
    </message>
    <message>
        <source>The 3D view&apos;s shaders could not be built: %1</source>
        <translation>Šejderi 3D prikaza nisu mogli da se izgrade: %1</translation>
    </message>
    <message>
        <source>A picture of %1 × %2 pixels is not possible: the largest is %3 × %3.</source>
        <translation>Slika od %1 × %2 piksela nije moguća: najveća je %3 × %3.</translation>
    </message>
    <message>
        <source>The OpenGL driver could not make a framebuffer of %1 × %2 pixels.</source>
        <translation>OpenGL drajver nije mogao da napravi bafer kadra od %1 × %2 piksela.</translation>
    </message>
    <message>
        <source>No OpenGL context could be created on the “%1” display platform.</source>
        <translation>OpenGL kontekst nije mogao da se napravi na platformi prikaza „%1“.</translation>
    </message>
    <message>
        <source>The driver offers OpenGL %1%2.%3 only.</source>
        <translation>Drajver nudi samo OpenGL %1%2.%3.</translation>
    </message>
    <message>
        <source>The OpenGL context could not be made current on an offscreen surface.</source>
        <translation>OpenGL kontekst nije mogao da postane tekući na površini van ekrana.</translation>
    </message>
</context>
<context>
    <name>pkm::RequirementsDialog</name>
    <message>
        <source>Requirements</source>
        <translation>Zahtevi</translation>
    </message>
    <message>
        <source>What the actuators must deliver at the platform. The workspace map “where the requirements hold” shows, in green, where every checked one does, from the actuators&apos; limits in the design.</source>
        <translation>Šta pogoni moraju da daju na platformi. Mapa radnog prostora „gde su zahtevi ispunjeni“ zelenom bojom pokazuje gde je ispunjen svaki označeni, prema granicama pogona u konstrukciji.</translation>
    </message>
    <message>
        <source>This design states no actuator limits: there is nothing to require.</source>
        <translation>Ova konstrukcija ne zadaje granice pogona: nema šta da se zahteva.</translation>
    </message>
    <message>
        <source>Also required (from the file, kept as it is): %1</source>
        <translation>Takođe se zahteva (iz datoteke, zadržano kakvo jeste): %1</translation>
    </message>
</context>
<context>
    <name>pkm::SetParameterCommand</name>
    <message>
        <source>Change %1</source>
        <translation>Promeni %1</translation>
    </message>
</context>
<context>
    <name>pkm::SweepPlotsPanel</name>
    <message>
        <source>&amp;Quantity:</source>
        <translation>&amp;Veličina:</translation>
    </message>
    <message>
        <source>%1 against %2</source>
        <translation>%1 (na apscisi: %2)</translation>
    </message>
</context>
<context>
    <name>pkm::TolerancePanel</name>
    <message>
        <source>Give a tolerance to at least one parameter.</source>
        <translation>Zadajte toleranciju bar jednom parametru.</translation>
    </message>
    <message>
        <source>First-order worst case at this pose: |Δx| ≤ %1 (%2).</source>
        <translation>Najgori slučaj u prvoj aproksimaciji u ovom položaju: |Δx| ≤ %1 (%2).</translation>
    </message>
    <message>
        <source>Monte Carlo</source>
        <translation>Monte Karlo</translation>
    </message>
    <message>
        <source>Solving %1 designs within the tolerances…</source>
        <translation>Rešavanje %1 konstrukcija u okviru tolerancija…</translation>
    </message>
    <message>
        <source>Monte Carlo cancelled.</source>
        <translation>Monte Karlo je otkazan.</translation>
    </message>
    <message>
        <source>%1 of %2 samples did not assemble (%3 %).</source>
        <translation>%1 od %2 uzoraka se nije sklopilo (%3 %).</translation>
    </message>
    <message>
        <source>No sample assembled: the distribution is undefined.</source>
        <translation>Nijedan uzorak se nije sklopio: raspodela nije definisana.</translation>
    </message>
    <message>
        <source>Monte Carlo |Δx|: mean %1, σ %2, max %3. %4</source>
        <translation>Monte Karlo |Δx|: srednja vrednost %1, σ %2, maks. %3. %4</translation>
    </message>
    <message>
        <source>|Δx| (%1)</source>
        <translation>|Δx| (%1)</translation>
    </message>
    <message>
        <source>samples</source>
        <translation>uzorci</translation>
    </message>
    <message>
        <source>This mechanism has no planar workspace to map.</source>
        <translation>Ovaj mehanizam nema ravanski radni prostor za mapu.</translation>
    </message>
    <message>
        <source>Worst-case map</source>
        <translation>Mapa najgoreg slučaja</translation>
    </message>
    <message>
        <source>Mapping the worst-case error over the workspace…</source>
        <translation>Mapiranje najgore greške po radnom prostoru…</translation>
    </message>
    <message>
        <source>Map cancelled.</source>
        <translation>Mapa je otkazana.</translation>
    </message>
    <message>
        <source>Worst case over the workspace: %1 to %2 (%3 cells; dark: small, bright: large).</source>
        <translation>Najgori slučaj po radnom prostoru: od %1 do %2 (%3 ćelija; tamno: malo, svetlo: veliko).</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Parametar</translation>
    </message>
    <message>
        <source>Tolerance</source>
        <translation>Tolerancija</translation>
    </message>
    <message>
        <source>Error part</source>
        <translation>Udeo greške</translation>
    </message>
    <message>
        <source>Share</source>
        <translation>Udeo</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>Parametri</translation>
    </message>
    <message>
        <source>Monte Carlo and map</source>
        <translation>Monte Karlo i mapa</translation>
    </message>
    <message>
        <source>Samples:</source>
        <translation>Uzoraka:</translation>
    </message>
    <message>
        <source>Normal (tol = 3σ)</source>
        <translation>Normalna (tolerancija = 3σ)</translation>
    </message>
    <message>
        <source>Draw normal samples with the tolerance as 3σ instead of uniform ones within ±tol</source>
        <translation>Uzimaj normalne uzorke sa tolerancijom kao 3σ umesto ravnomernih u okviru ±tolerancije</translation>
    </message>
    <message>
        <source>Solve many designs drawn within the tolerances at this pose (fixed seed)</source>
        <translation>Reši mnogo konstrukcija uzetih u okviru tolerancija u ovom položaju (fiksno seme)</translation>
    </message>
    <message>
        <source>Map</source>
        <translation>Mapa</translation>
    </message>
    <message>
        <source>The first-order worst case over the workspace</source>
        <translation>Najgori slučaj u prvoj aproksimaciji po radnom prostoru</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Obriši</translation>
    </message>
    <message>
        <source>Remove every tolerance (undoable)</source>
        <translation>Ukloni sve tolerancije (može se opozvati)</translation>
    </message>
</context>
<context>
    <name>pkm::ValuesTable</name>
    <message>
        <source>Pose</source>
        <translation>Položaj</translation>
    </message>
    <message>
        <source>Jacobian</source>
        <translation>Jakobijan</translation>
    </message>
    <message>
        <source>Derived</source>
        <translation>Izvedene veličine</translation>
    </message>
    <message>
        <source>none</source>
        <translation>nema</translation>
    </message>
    <message>
        <source>inverse</source>
        <translation>inverzni</translation>
    </message>
    <message>
        <source>direct</source>
        <translation>direktni</translation>
    </message>
    <message>
        <source>combined</source>
        <translation>kombinovani</translation>
    </message>
    <message>
        <source>Quantity</source>
        <translation>Veličina</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Vrednost</translation>
    </message>
    <message>
        <source>Meaning</source>
        <translation>Opis</translation>
    </message>
    <message>
        <source>Singularity</source>
        <translation>Singularitet</translation>
    </message>
    <message>
        <source>class</source>
        <translation>klasa</translation>
    </message>
    <message>
        <source>none, inverse, direct or combined</source>
        <translation>nema, inverzni, direktni ili kombinovani</translation>
    </message>
    <message>
        <source>%1 (margin %2)</source>
        <translation>%1 (udaljenost %2)</translation>
    </message>
    <message>
        <source>Capability</source>
        <translation>Mogućnosti pogona</translation>
    </message>
    <message>
        <source>Capability: as at a singular pose</source>
        <translation>Mogućnosti: kao u singularnom položaju</translation>
    </message>
    <message>
        <source>near inverse</source>
        <translation>blizu inverznog</translation>
    </message>
    <message>
        <source>near direct</source>
        <translation>blizu direktnog</translation>
    </message>
    <message>
        <source>near combined</source>
        <translation>blizu kombinovanog</translation>
    </message>
    <message>
        <source>Point at a row to read its meaning in full.</source>
        <translation>Postavite pokazivač na red da pročitate njegovo značenje u celosti.</translation>
    </message>
</context>
<context>
    <name>pkm::VariablePanel</name>
    <message>
        <source>input, actuated</source>
        <translation>ulaz, sa pogonom</translation>
    </message>
    <message>
        <source>input</source>
        <translation>ulaz</translation>
    </message>
    <message>
        <source>output</source>
        <translation>izlaz</translation>
    </message>
    <message>
        <source>Drag to set %1 (%2), from %3 to %4</source>
        <translation>Prevucite da podesite %1 (%2), od %3 do %4</translation>
    </message>
</context>
<context>
    <name>pkm::VideoWriter</name>
    <message>
        <source>A video is %1 to %2 pixels wide and %1 to %3 high, in even numbers (e.g. 1280x720 or 1920x1080), not %4x%5.</source>
        <translation>Video je širok od %1 do %2 i visok od %1 do %3 piksela, u parnim brojevima (npr. 1280x720 ili 1920x1080), a ne %4x%5.</translation>
    </message>
    <message>
        <source>Cannot write &apos;%1&apos;: %2.</source>
        <translation>Ne može da se upiše „%1“: %2.</translation>
    </message>
    <message>
        <source>unknown error</source>
        <translation>nepoznata greška</translation>
    </message>
    <message>
        <source>This build of FFmpeg&apos;s libavformat cannot write %1 files.</source>
        <translation>Ova verzija FFmpeg-ove biblioteke libavformat ne može da piše %1 datoteke.</translation>
    </message>
    <message>
        <source>FFmpeg is out of memory.</source>
        <translation>FFmpeg-u je ponestalo memorije.</translation>
    </message>
    <message>
        <source>FFmpeg could not start the %1 encoder (%2): %3.</source>
        <translation>FFmpeg nije mogao da pokrene %1 koder (%2): %3.</translation>
    </message>
    <message>
        <source>FFmpeg&apos;s libavcodec here has no H.264 encoder: MP4 needs libx264 (Debian&apos;s libavcodec has it).</source>
        <translation>FFmpeg-ov libavcodec ovde nema H.264 koder: za MP4 je potreban libx264 (Debian-ov libavcodec ga ima).</translation>
    </message>
    <message>
        <source>FFmpeg&apos;s libavcodec here has no VP9 or VP8 encoder: WebM needs libvpx (Debian&apos;s libavcodec has it).</source>
        <translation>FFmpeg-ov libavcodec ovde nema VP9 ni VP8 koder: za WebM je potreban libvpx (Debian-ov libavcodec ga ima).</translation>
    </message>
    <message>
        <source>FFmpeg&apos;s libswscale cannot convert the frames to YUV 4:2:0.</source>
        <translation>FFmpeg-ov libswscale ne može da pretvori kadrove u YUV 4:2:0.</translation>
    </message>
    <message>
        <source>The video is not open.</source>
        <translation>Video nije otvoren.</translation>
    </message>
    <message>
        <source>A video needs at least one frame.</source>
        <translation>Video mora da ima bar jedan kadar.</translation>
    </message>
</context>
<context>
    <name>pkm::View3DPanel</name>
    <message>
        <source>Names</source>
        <translation>Imena</translation>
    </message>
    <message>
        <source>The names of the joints (A, B, … as in the 2D view) over the model</source>
        <translation>Imena zglobova (A, B, … kao u 2D prikazu) preko modela</translation>
    </message>
    <message>
        <source>Fit</source>
        <translation>Uklopi</translation>
    </message>
    <message>
        <source>Show the whole mechanism (F, or double-click)</source>
        <translation>Prikaži ceo mehanizam (F ili dvostruki klik)</translation>
    </message>
    <message>
        <source>Front</source>
        <translation>Spreda</translation>
    </message>
    <message>
        <source>Look at the mechanism plane, as the 2D view does (1)</source>
        <translation>Pogled na ravan mehanizma, kao u 2D prikazu (1)</translation>
    </message>
    <message>
        <source>Top</source>
        <translation>Odozgo</translation>
    </message>
    <message>
        <source>Look down from above (7)</source>
        <translation>Pogled odozgo nadole (7)</translation>
    </message>
    <message>
        <source>Side</source>
        <translation>Sa strane</translation>
    </message>
    <message>
        <source>Look from the right (3)</source>
        <translation>Pogled zdesna (3)</translation>
    </message>
    <message>
        <source>Isometric</source>
        <translation>Izometrija</translation>
    </message>
    <message>
        <source>Look from the front, right and above at once</source>
        <translation>Pogled istovremeno spreda, zdesna i odozgo</translation>
    </message>
    <message>
        <source>Perspective</source>
        <translation>Perspektiva</translation>
    </message>
    <message>
        <source>Perspective when on, orthographic (true to scale) when off (5)</source>
        <translation>Uključeno — perspektiva, isključeno — ortogonalna projekcija (u razmeri) (5)</translation>
    </message>
    <message>
        <source>Save picture…</source>
        <translation>Sačuvaj sliku…</translation>
    </message>
    <message>
        <source>Save the 3D view as a PNG picture at twice its size</source>
        <translation>Sačuvaj 3D prikaz kao PNG sliku dvostruke veličine</translation>
    </message>
    <message>
        <source>%1 × %2 pixels is not a picture size: each side must be from 16 to 8000.</source>
        <translation>%1 × %2 piksela nije ispravna veličina slike: svaka stranica mora biti od 16 do 8000.</translation>
    </message>
    <message>
        <source>The picture could not be rendered. %1</source>
        <translation>Slika nije mogla da se iscrta. %1</translation>
    </message>
    <message>
        <source>“%1” could not be opened for writing: %2</source>
        <translation>Datoteka „%1“ nije mogla da se otvori za upis: %2</translation>
    </message>
    <message>
        <source>The picture could not be written to “%1”.</source>
        <translation>Slika nije mogla da se upiše u „%1“.</translation>
    </message>
    <message>
        <source>“%1” could not be saved: %2</source>
        <translation>Datoteka „%1“ nije mogla da se sačuva: %2</translation>
    </message>
    <message>
        <source>Save picture</source>
        <translation>Sačuvaj sliku</translation>
    </message>
    <message>
        <source>PNG pictures (*.png)</source>
        <translation>PNG slike (*.png)</translation>
    </message>
    <message>
        <source>%1 × %2 pixels</source>
        <translation>%1 × %2 piksela</translation>
    </message>
    <message>
        <source>%1 (twice the view)</source>
        <translation>%1 (dvostruko veća od prikaza)</translation>
    </message>
    <message>
        <source>Picture size:</source>
        <translation>Veličina slike:</translation>
    </message>
</context>
<context>
    <name>pkm::ViewPicture</name>
    <message>
        <source>Save 2D View Picture</source>
        <translation>Sačuvaj sliku 2D prikaza</translation>
    </message>
</context>
<context>
    <name>pkm::WorkspaceMapView</name>
    <message>
        <source>No mechanism.</source>
        <translation>Nema mehanizma.</translation>
    </message>
    <message>
        <source>No planar workspace: the outputs of this mechanism are not a point of the plane, so there is no workspace map to show.</source>
        <translation>Nema ravnog radnog prostora: izlazne koordinate ovog mehanizma nisu tačka ravni, pa nema mape radnog prostora za prikaz.</translation>
    </message>
    <message>
        <source>Workspace map</source>
        <translation>Mapa radnog prostora</translation>
    </message>
    <message>
        <source>Workspace empty in the design&apos;s working and assembly modes</source>
        <translation>Radni prostor je prazan u radnom režimu i načinu sklapanja ove konstrukcije</translation>
    </message>
    <message>
        <source>κ(J), log scale (colours end at %1)</source>
        <translation>κ(J), logaritamska skala (boje do %1)</translation>
    </message>
    <message>
        <source>det J (colours clipped at ±%1)</source>
        <translation>det J (boje ograničene na ±%1)</translation>
    </message>
    <message>
        <source>The colours end at the 98th percentile of κ(J) over the workspace, %1; κ → ∞ at the singularities.</source>
        <translation>Skala boja se završava na 98. percentilu κ(J) u radnom prostoru, %1; u singularitetima κ → ∞.</translation>
    </message>
    <message>
        <source>The colours are clipped at ±%1, the larger of the 5th and 95th percentiles of |det J| over the workspace: det J → ±∞ at inverse singularities, 0 at direct ones.</source>
        <translation>Boje su ograničene na ±%1, veći od 5. i 95. percentila |det J| u radnom prostoru: u singularitetima inverzne kinematike det J → ±∞, u singularitetima direktne kinematike 0.</translation>
    </message>
    <message>
        <source>workspace boundary</source>
        <translation>granica radnog prostora</translation>
    </message>
    <message>
        <source>: none</source>
        <translation>: nema</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>inverse singularity</source>
        <translation>singularitet inverzne kinematike</translation>
    </message>
    <message>
        <source>direct singularity</source>
        <translation>singularitet direktne kinematike</translation>
    </message>
    <message>
        <source>%1: boundary, %2</source>
        <translation>%1: granica, %2</translation>
    </message>
    <message>
        <source> (%1%2 %)</source>
        <translation> (%1%2 %)</translation>
    </message>
    <message>
        <source>&amp;Map:</source>
        <translation>&amp;Mapa:</translation>
    </message>
    <message>
        <source>condition number κ(J)</source>
        <translation>broj uslovljenosti κ(J)</translation>
    </message>
    <message>
        <source>computing…</source>
        <translation>računam…</translation>
    </message>
    <message>
        <source>x (mm)</source>
        <translation>x (mm)</translation>
    </message>
    <message>
        <source>y (mm)</source>
        <translation>y (mm)</translation>
    </message>
    <message>
        <source>Workspace %1 · orientation range of φ from %2° to %3°</source>
        <translation>Radni prostor %1 · opseg orijentacije φ od %2° do %3°</translation>
    </message>
    <message>
        <source>orientation range of φ (°): the angles that hold the platform</source>
        <translation>opseg orijentacije φ (°): uglovi u kojima noge drže platformu</translation>
    </message>
    <message>
        <source>At each point, the total width of the platform angles φ at which the legs can hold it there; the map&apos;s outline is the workspace at φ_map.</source>
        <translation>U svakoj tački ukupna širina uglova platforme φ pri kojima je noge mogu držati tu; kontura mape je radni prostor pri φ_map.</translation>
    </message>
    <message>
        <source>orientation range of φ</source>
        <translation>opseg orijentacije φ</translation>
    </message>
    <message>
        <source>force in the weakest direction</source>
        <translation>sila u najslabijem pravcu</translation>
    </message>
    <message>
        <source>speed in the slowest direction</source>
        <translation>brzina u najsporijem pravcu</translation>
    </message>
    <message>
        <source>worst resolution</source>
        <translation>najgora rezolucija</translation>
    </message>
    <message>
        <source>stiffness in the weakest direction</source>
        <translation>krutost u najslabijem pravcu</translation>
    </message>
    <message>
        <source>where the requirements hold</source>
        <translation>gde su zahtevi ispunjeni</translation>
    </message>
    <message>
        <source>Requirements met in %1 of the workspace %2 (%3 %)</source>
        <translation>Zahtevi ispunjeni na %1 od radnog prostora %2 (%3 %)</translation>
    </message>
    <message>
        <source>green: every requirement holds; grey: one fails</source>
        <translation>zeleno: svi zahtevi ispunjeni; sivo: jedan nije</translation>
    </message>
    <message>
        <source>Required: %1</source>
        <translation>Zahteva se: %1</translation>
    </message>
    <message>
        <source>%1 (%2): %3, colours end at %4</source>
        <translation>%1 (%2): %3, boje do %4</translation>
    </message>
    <message>
        <source>What the actuators deliver at each point of the workspace, from their limits in the design: 0 or ∞ exactly at a singularity. Every cell is the value of the pose solved there.</source>
        <translation>Šta pogoni daju u svakoj tački radnog prostora, prema svojim granicama u konstrukciji: tačno 0 ili ∞ u singularnom položaju. Svaka ćelija je vrednost položaja rešenog u toj tački.</translation>
    </message>
    <message>
        <source>No requirements stated (Edit ▸ Requirements…): the whole workspace %1 meets them</source>
        <translation>Nisu zadati zahtevi (Uređivanje ▸ Zahtevi…): ceo radni prostor %1 ih ispunjava</translation>
    </message>
    <message>
        <source>State what the actuators must deliver with Edit ▸ Requirements….</source>
        <translation>Zadajte šta pogoni moraju da daju u meniju Uređivanje ▸ Zahtevi….</translation>
    </message>
    <message>
        <source>The first-order worst-case error of the platform point at each point of the workspace, from the tolerances of the Tolerances panel: ∞ at a direct singularity.</source>
        <translation>Najveća greška tačke platforme u prvom približenju u svakoj tački radnog prostora, prema tolerancijama panela „Tolerancije”: ∞ u singularitetu direktne kinematike.</translation>
    </message>
    <message>
        <source>worst-case error from the tolerances</source>
        <translation>najveća greška od tolerancija</translation>
    </message>
    <message>
        <source>Workspace %1 · %2 from %3 to %4%5 at the grid points</source>
        <translation>Radni prostor %1 · %2 od %3 do %4%5 u čvorovima mreže</translation>
    </message>
    <message>
        <source>%1 at φ = %2</source>
        <translation>%1 pri φ = %2</translation>
    </message>
    <message>
        <source>Workspace %1 · %2 from %3 to %4 at the grid points</source>
        <translation>Radni prostor %1 · %2 od %3 do %4 u čvorovima mreže</translation>
    </message>
    <message>
        <source>%1 at φ = %2, not the pose&apos;s φ</source>
        <translation>%1 pri φ = %2 (položaj ima drugi ugao φ)</translation>
    </message>
    <message>
        <source>range of φ (°)</source>
        <translation>opseg φ (°)</translation>
    </message>
    <message>
        <source>κ(J), log scale</source>
        <translation>κ(J), log. skala</translation>
    </message>
    <message>
        <source>Workspace %1</source>
        <translation>Radni prostor %1</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>pkm::WorkspacePanel</name>
    <message>
        <source>Compare workspace with:</source>
        <translation>Uporedi radni prostor sa:</translation>
    </message>
    <message>
        <source>Pin this design</source>
        <translation>Zapamti ovu konstrukciju</translation>
    </message>
    <message>
        <source>Keep the current design&apos;s workspace as the comparison, then change the design and see both outlines.</source>
        <translation>Zadržava radni prostor trenutne konstrukcije za poređenje, pa možete da promenite konstrukciju i vidite obe konture.</translation>
    </message>
    <message>
        <source>nothing</source>
        <translation>ničim</translation>
    </message>
    <message>
        <source>pinned: %1</source>
        <translation>zapamćena: %1</translation>
    </message>
    <message>
        <source>pinned</source>
        <translation>zapamćena</translation>
    </message>
</context>
<context>
    <name>pkm::designfile</name>
    <message>
        <source>%1 is not valid JSON (%2 at byte %3).</source>
        <translation>%1 nije ispravan JSON (%2 na bajtu %3).</translation>
    </message>
    <message>
        <source>%1 is not a PKM Studio design file.</source>
        <translation>%1 nije datoteka konstrukcije programa PKM Studio.</translation>
    </message>
    <message>
        <source>%1 was written by a newer PKM Studio (format version %2; this version reads up to %3).</source>
        <translation>%1 je zapisan novijom verzijom programa PKM Studio (verzija formata %2; ova verzija čita do %3).</translation>
    </message>
    <message>
        <source>%1 has no valid format version.</source>
        <translation>%1 nema ispravnu verziju formata.</translation>
    </message>
    <message>
        <source>%1 names an unknown mechanism kind &apos;%2&apos;.</source>
        <translation>%1 navodi nepoznatu vrstu mehanizma „%2“.</translation>
    </message>
    <message>
        <source>%1: unknown parameter &apos;%2&apos;.</source>
        <translation>%1: nepoznat parametar „%2“.</translation>
    </message>
    <message>
        <source>%1: parameter &apos;%2&apos; is not a number.</source>
        <translation>%1: parametar „%2“ nije broj.</translation>
    </message>
    <message>
        <source>%1: parameter &apos;%2&apos; must be a number or one of %3, not &apos;%4&apos;.</source>
        <translation>%1: parametar „%2“ mora biti broj ili jedna od vrednosti %3, a ne „%4“.</translation>
    </message>
    <message>
        <source>%1: pose value &apos;%2&apos; is not a number.</source>
        <translation>%1: vrednost položaja „%2“ nije broj.</translation>
    </message>
    <message>
        <source>the pose&apos;s %1 = %2 %4 does not agree with its inputs, which give %3 %4.</source>
        <translation>vrednost položaja %1 = %2 %4 ne slaže se sa ulaznim koordinatama, koje daju %3 %4.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is neither a preset id (see &apos;pkm list&apos;) nor a design file.</source>
        <translation>„%1“ nije ni oznaka šablona (videti „pkm list“) ni datoteka konstrukcije.</translation>
    </message>
    <message>
        <source>Cannot open %1: %2.</source>
        <translation>Nije moguće otvoriti %1: %2.</translation>
    </message>
    <message>
        <source>Cannot write %1: %2.</source>
        <translation>Nije moguće upisati %1: %2.</translation>
    </message>
    <message>
        <source>Unknown parameter &apos;%1&apos; (see &apos;pkm show&apos;).</source>
        <translation>Nepoznat parametar „%1“ (videti „pkm show“).</translation>
    </message>
    <message>
        <source>Unknown pose variable &apos;%1&apos;.</source>
        <translation>Nepoznata promenljiva položaja „%1“.</translation>
    </message>
    <message>
        <source>Give either the actuated inputs or the outputs of the pose, not both.</source>
        <translation>Zadajte ili pogonske (ulazne) ili izlazne koordinate položaja, ali ne obe.</translation>
    </message>
    <message>
        <source>%1: “bookmarks” is not a list.</source>
        <translation>%1: „bookmarks” nije lista.</translation>
    </message>
    <message>
        <source>%1 has more than %2 bookmarks.</source>
        <translation>%1 ima više od %2 obeleživača.</translation>
    </message>
    <message>
        <source>%1: a bookmark&apos;s name is longer than %2 characters.</source>
        <translation>%1: ime obeleživača je duže od %2 znakova.</translation>
    </message>
    <message>
        <source>%1: bookmark “%2” has an invalid pose value &apos;%3&apos;.</source>
        <translation>%1: obeleživač „%2” ima nevažeću vrednost položaja „%3”.</translation>
    </message>
    <message>
        <source>%1: “tolerances” is not an object.</source>
        <translation>%1: „tolerances” nije objekat.</translation>
    </message>
    <message>
        <source>%1 has more than %2 tolerances.</source>
        <translation>%1 ima više od %2 tolerancija.</translation>
    </message>
    <message>
        <source>it is not a number</source>
        <translation>to nije broj</translation>
    </message>
    <message>
        <source>%1: the tolerance of &apos;%2&apos; is refused: %3</source>
        <translation>%1: tolerancija za „%2” je odbijena: %3</translation>
    </message>
    <message>
        <source>%1: “requirements” is not a list of texts.</source>
        <translation>%1: „requirements“ nije lista tekstova.</translation>
    </message>
    <message>
        <source>%1: “requirements” has more than %2 entries.</source>
        <translation>%1: „requirements“ ima više od %2 stavki.</translation>
    </message>
    <message>
        <source>%1: “requirements” holds an entry that is not a text of at most %2 characters.</source>
        <translation>%1: „requirements“ sadrži stavku koja nije tekst od najviše %2 znakova.</translation>
    </message>
    <message>
        <source>%1: “requirements”: %2</source>
        <translation>%1: „requirements“: %2</translation>
    </message>
    <message>
        <source>%1 is larger than %2 MiB, the most a design file may be.</source>
        <translation>%1 je veća od %2 MiB, koliko najviše datoteka konstrukcije sme da ima.</translation>
    </message>
    <message>
        <source>%1: the title is longer than %2 characters, the most a design keeps.</source>
        <translation>%1: naslov je duži od %2 znakova, koliko najviše konstrukcija čuva.</translation>
    </message>
    <message>
        <source>%1: the description is longer than %2 characters, the most a design keeps.</source>
        <translation>%1: opis je duži od %2 znakova, koliko najviše konstrukcija čuva.</translation>
    </message>
</context>
<context>
    <name>presets</name>
    <message>
        <source>Planar five-bar linkage (example)</source>
        <translation>Ravanski petočlani mehanizam (primer)</translation>
    </message>
    <message>
        <source>Four-bar linkage example (crank-rocker 40/120/100/140 mm)</source>
        <translation>Primer zglobnog četvorougla (poluga–klackalica 40/120/100/140 mm)</translation>
    </message>
    <message>
        <source>MOMA configuration 3a (γ₁ = −5°, γ₂ = +5°)</source>
        <translation>MOMA, konfiguracija 3a (γ₁ = −5°, γ₂ = +5°)</translation>
    </message>
    <message>
        <source>Configuration of fig. 3a: R₁ = (−100, 0) mm, R₂ = (100, 0) mm, guides turned from the vertical by γ₁ = −5° and γ₂ = +5° (α_i = 270° + γ_i), so they open downwards. Links l₁ = l₂ = 195 mm, strokes h = 200 mm (p from 0 to 200 mm, measured from R_i along the guide). Both legs work with p_i = B_i − √(B_i² − C_i), the platform below the sliders. The document finds no direct singularities in this workspace.</source>
        <translation>Konfiguracija sa sl. 3a: R₁ = (−100, 0) mm, R₂ = (100, 0) mm, vođice zaokrenute od vertikale za γ₁ = −5° i γ₂ = +5° (α_i = 270° + γ_i), tako da se šire naniže. Spojke l₁ = l₂ = 195 mm, hodovi h = 200 mm (p od 0 do 200 mm, mereno od R_i duž vođice). Obe grane rade sa p_i = B_i − √(B_i² − C_i), platforma je ispod klizača. Dokument ne nalazi singularitete direktne kinematike u ovom radnom prostoru.</translation>
    </message>
    <message>
        <source>MOMA configuration 3b (γ₁ = +5°, γ₂ = −5°)</source>
        <translation>MOMA, konfiguracija 3b (γ₁ = +5°, γ₂ = −5°)</translation>
    </message>
    <message>
        <source>Configuration of fig. 3b: as 3a with the guides turned the other way, γ₁ = +5° and γ₂ = −5°, so they close downwards. Links l₁ = l₂ = 195 mm, strokes h = 200 mm (p from 0 to 200 mm, measured from R_i along the guide). The document finds no direct singularities in this workspace.</source>
        <translation>Konfiguracija sa sl. 3b: kao 3a, sa vođicama zaokrenutim na drugu stranu, γ₁ = +5° i γ₂ = −5°, tako da se sužavaju naniže. Spojke l₁ = l₂ = 195 mm, hodovi h = 200 mm (p od 0 do 200 mm, mereno od R_i duž vođice). Dokument ne nalazi singularitete direktne kinematike u ovom radnom prostoru.</translation>
    </message>
    <message>
        <source>MOMA configuration 3c (interpreted)</source>
        <translation>MOMA, konfiguracija 3c (tumačenje)</translation>
    </message>
    <message>
        <source>Interpreted: the document describes 3c in two ways that do not agree (the guides along the axes, or α = 225°/315° turned by β through the matrices (15–16)), and its figure is missing; this preset takes the first. Configuration of fig. 3c: R₁ = (250, 0) mm with α₁ = 180° and R₂ = (0, 250) mm with α₂ = 270°, the guides along the axes towards the corner. Links l₁ = l₂ = 195 mm, strokes h = 200 mm (p from 0 to 200 mm, measured from R_i along the guide). Here both legs take the document&apos;s root p_i = B_i − √…; every inverse singularity lies on x = 195 mm or y = 195 mm (a link perpendicular to its guide), where the document puts them, at the edge of the other assembly mode&apos;s region near (195, 195) mm; the direct singularity needs both slider joints at the origin, beyond the strokes.</source>
        <translation>Tumačenje: dokument opisuje 3c na dva načina koji se ne slažu (vođice duž osa, ili α = 225°/315° zaokrenute za β matricama (15–16)), a slika nedostaje; ovaj šablon uzima prvi. Konfiguracija sa sl. 3c: R₁ = (250, 0) mm sa α₁ = 180° i R₂ = (0, 250) mm sa α₂ = 270°, vođice duž osa ka uglu. Spojke l₁ = l₂ = 195 mm, hodovi h = 200 mm (p od 0 do 200 mm, mereno od R_i duž vođice). Ovde obe grane uzimaju koren iz dokumenta p_i = B_i − √…; svi singulariteti inverzne kinematike leže na x = 195 mm ili y = 195 mm (spojka upravna na svoju vođicu), gde ih dokument i postavlja, na ivici oblasti drugog načina sklapanja blizu (195, 195) mm; singularitet direktne kinematike zahteva da oba zgloba klizača budu u koordinatnom početku, izvan hodova.</translation>
    </message>
    <message>
        <source>MOMA configuration 3d (interpreted)</source>
        <translation>MOMA, konfiguracija 3d (tumačenje)</translation>
    </message>
    <message>
        <source>Interpreted: the document describes 3d in two ways that do not agree (the guides along the axes, or α = 225°/315° turned by β through the matrices (15–16)), and its figure is missing; this preset takes the first. Configuration of fig. 3d: R₁ = (117, 0) mm with α₁ = 0° and R₂ = (0, 117) mm with α₂ = 90°, the guides along the axes away from the corner, the platform between them near the origin. Links l₁ = l₂ = 195 mm, strokes h = 200 mm (p from 0 to 200 mm, measured from R_i along the guide). Here both legs take the root p_i = B_i + √… that keeps the platform on the corner side of the sliders; the direct singularities (links stretched in line) bound the workspace on the far side.</source>
        <translation>Tumačenje: dokument opisuje 3d na dva načina koji se ne slažu (vođice duž osa, ili α = 225°/315° zaokrenute za β matricama (15–16)), a slika nedostaje; ovaj šablon uzima prvi. Konfiguracija sa sl. 3d: R₁ = (117, 0) mm sa α₁ = 0° i R₂ = (0, 117) mm sa α₂ = 90°, vođice duž osa u smeru od ugla, platforma između njih blizu koordinatnog početka. Spojke l₁ = l₂ = 195 mm, hodovi h = 200 mm (p od 0 do 200 mm, mereno od R_i duž vođice). Ovde obe grane uzimaju koren p_i = B_i + √… koji drži platformu sa strane ugla u odnosu na klizače; singulariteti direktne kinematike (spojke opružene u liniju) ograničavaju radni prostor sa udaljene strane.</translation>
    </message>
    <message>
        <source>O-X glide prototype (l = 80 mm, s = 20 mm, L = 130 mm)</source>
        <translation>Prototip mehanizma O-X glide (l = 80 mm, s = 20 mm, L = 130 mm)</translation>
    </message>
    <message>
        <source>The rapid-prototyped O-X glide of the Novi Sad document: rods l = 80 mm, platform width s = 20 mm, transverse guides L = 130 mm (slider positions 0 to 130 mm), working in the extended (O) form. The guide spacing a = 15 mm and the longitudinal travel z = 0 to 150 mm are not given in the document and are chosen for the drawing; they do not change the planar workspace.</source>
        <translation>Brzo prototipizovani O-X glide mehanizam iz novosadskog dokumenta: štapovi l = 80 mm, širina platforme s = 20 mm, poprečne vođice L = 130 mm (položaji klizača od 0 do 130 mm), rad u opruženom (O) obliku. Rastojanje između vođica a = 15 mm i uzdužni hod z od 0 do 150 mm nisu dati u dokumentu i izabrani su za crtež; oni ne menjaju ravanski radni prostor.</translation>
    </message>
    <message>
        <source>П-joint laboratory prototype (a = 170 mm, k = 0.4)</source>
        <translation>Laboratorijski prototip P-zgloba (a = 170 mm, k = 0,4)</translation>
    </message>
    <message>
        <source>The laboratory prototype of section 4.2: a = 170 mm, b = 68 mm (k = 0.4), θ = ±60°, driven by the hybrid stepper motor with integrated lead screw of Table 1 (lead 2.54 mm, 0.0127 mm/step, 50 mm/s, 130 N). The screw efficiency 0.4 is an assumption: Table 1 does not give it.</source>
        <translation>Laboratorijski prototip iz odeljka 4.2: a = 170 mm, b = 68 mm (k = 0,4), θ = ±60°, pokretan hibridnim koračnim motorom sa ugrađenim zavojnim vretenom iz tabele 1 (korak 2,54 mm, 0,0127 mm/korak, 50 mm/s, 130 N). Stepen iskorišćenja vretena 0,4 je pretpostavka: tabela 1 ga ne navodi.</translation>
    </message>
    <message>
        <source>П-joint design study k = 0.3 (a = 1 m)</source>
        <translation>Projektna studija P-zgloba, k = 0,3 (a = 1 m)</translation>
    </message>
    <message>
        <source>Design study of figures 8–12: a = 1 m, k = 0.3, θ over ±75°, with the stepper motor of Table 1.</source>
        <translation>Projektna studija sa slika 8–12: a = 1 m, k = 0,3, θ u opsegu ±75°, sa koračnim motorom iz tabele 1.</translation>
    </message>
    <message>
        <source>П-joint design study k = 0.4 (a = 1 m)</source>
        <translation>Projektna studija P-zgloba, k = 0,4 (a = 1 m)</translation>
    </message>
    <message>
        <source>Design study of figures 8–12: a = 1 m, k = 0.4, θ over ±75°, with the stepper motor of Table 1.</source>
        <translation>Projektna studija sa slika 8–12: a = 1 m, k = 0,4, θ u opsegu ±75°, sa koračnim motorom iz tabele 1.</translation>
    </message>
    <message>
        <source>П-joint design study k = 0.5 (a = 1 m)</source>
        <translation>Projektna studija P-zgloba, k = 0,5 (a = 1 m)</translation>
    </message>
    <message>
        <source>Design study of figures 8–12: a = 1 m, k = 0.5, θ over ±75°, with the stepper motor of Table 1.</source>
        <translation>Projektna studija sa slika 8–12: a = 1 m, k = 0,5, θ u opsegu ±75°, sa koračnim motorom iz tabele 1.</translation>
    </message>
    <message>
        <source>A classroom five-bar chosen for PKM Studio (the four-bar and mobility document of Khabibullina, Khabibullin and Islamov shows the planar five-bar in its fig. 1 without dimensions). Ground AE = 100 mm; cranks AB = DE = 80 mm, driven at A and at E and turning fully; distal links BC = CD = 120 mm, meeting at the output point C. Chebyshev&apos;s count W = 3·4 − 2·5 = 2: the two crank angles θ₁, θ₄ fix C. Working modes elbows out (B to the left of A→C, D to the right of E→C), assembly mode C above BD (to the left of B→D). At C = (50, 150) mm each distal link is nearly perpendicular to its crank and the distal links nearly perpendicular to each other, so κ(J) ≈ 1.11; the workspace of these modes is bounded by the legs stretched or folded in line and, low between A and E, by a direct singularity where BC and CD come in line.</source>
        <translation>Nastavni petočlani mehanizam izabran za PKM Studio (dokument Habibuline, Habibulina i Islamova o zglobnom četvorouglu i pokretljivosti prikazuje ravanski petočlani mehanizam na sl. 1 bez dimenzija). Postolje AE = 100 mm; poluge AB = DE = 80 mm, pogonjene u A i u E, okreću se punim krugom; krajnje spojke BC = CD = 120 mm spajaju se u izlaznoj tački C. Po Čebiševljevoj formuli W = 3·4 − 2·5 = 2: dva ugla poluga θ₁, θ₄ određuju položaj C. Radni režimi „laktovi ka spolja“ (B levo od A→C, D desno od E→C), način sklapanja C iznad BD (levo od B→D). Za C = (50, 150) mm svaka krajnja spojka je skoro upravna na svoju polugu, a krajnje spojke skoro upravne jedna na drugu, pa je κ(J) ≈ 1,11; radni prostor ovih režima ograničen je položajima u kojima su grane opružene ili sklopljene u liniju i, nisko između A i E, singularitetom direktne kinematike gde BC i CD dolaze u istu liniju.</translation>
    </message>
    <message>
        <source>An example crank-rocker chosen for PKM Studio: the four-bar document of Khabibullina, Khabibullin and Islamov gives no link lengths, so these are not the document&apos;s. Crank AB = 40 mm, coupler BC = 120 mm, rocker CD = 100 mm, ground AD = 140 mm: s + l = 180 mm &lt; p + q = 220 mm with the crank the shortest link, so the crank turns fully (α from 0° to 360°) and the rocker swings; the transmission angle stays between 53° and 110°. Open branch, ω₁ = 10 rad/s, coupler point M at the middle of BC.</source>
        <translation>Primer mehanizma poluga–klackalica izabran za PKM Studio: dokument Habibuline, Habibulina i Islamova o zglobnom četvorouglu ne daje dužine članova, pa ove vrednosti nisu iz dokumenta. Poluga AB = 40 mm, spojka BC = 120 mm, klackalica CD = 100 mm, postolje AD = 140 mm: s + l = 180 mm &lt; p + q = 220 mm, a poluga je najkraći član, pa se poluga okreće punim krugom (α od 0° do 360°), a klackalica osciluje; ugao prenosa ostaje između 53° i 110°. Otvorena grana, ω₁ = 10 rad/s, tačka spojke M na sredini BC.</translation>
    </message>
    <message>
        <source>Planar parallel: MOMA configuration 3a from two P̲RR legs</source>
        <translation>Ravanski paralelni: konfiguracija MOMA 3a od dve noge P̲RR</translation>
    </message>
    <message>
        <source>MOMA configuration 3a (Vasilić and Živanović, the MOMA document, fig. 3a) rebuilt from the leg library: two P̲RR legs on guides from R₁ = (−100, 0) and R₂ = (100, 0) mm turned by γ = ∓5° from the vertical (α = 265°, 275°), strokes 0 to 200 mm, links 195 mm, both legs with q = B − √…, the platform right of C₁→C₂. Its poses and Jacobians are the MOMA kind&apos;s.</source>
        <translation>Konfiguracija MOMA 3a (Vasić i Živanović, dokument o MOMA, sl. 3a) sastavljena iz biblioteke nogu: dve noge P̲RR na vođicama od R₁ = (−100, 0) i R₂ = (100, 0) mm, zakrenutim za γ = ∓5° od vertikale (α = 265°, 275°), hodovi od 0 do 200 mm, spojke 195 mm, obe noge sa q = B − √…, platforma desno od C₁→C₂. Njene poze i Jakobijeve matrice iste su kao kod vrste MOMA.</translation>
    </message>
    <message>
        <source>Planar parallel: a 3-RP̲R with six assembly modes</source>
        <translation>Ravanski paralelni: 3-RP̲R sa šest načina sklapanja</translation>
    </message>
    <message>
        <source>The 3-RP̲R of Innocenti and Parenti-Castelli, studied by Zein, Wenger and Chablat (Non-singular assembly-mode changing motions for 3-RPR parallel manipulators, Mechanism and Machine Theory, 2008): base joints A₁ = (0, 0), A₂ = (15.91, 0), A₃ = (0, 10), platform sides B₁B₂ = 17.04, B₂B₃ = 16.54, B₃B₁ = 20.84. At the strut lengths 14.98, 15.38 and 12 its direct kinematics has six real solutions.</source>
        <translation>Mehanizam 3-RP̲R Inoćentija i Parenti-Kastelija, koji su proučavali Zein, Venger i Šabla (članak o prelazima između načina sklapanja 3-RP̲R bez singulariteta, časopis „Teorija mehanizama i mašina”, 2008): zglobovi osnove A₁ = (0; 0), A₂ = (15,91; 0), A₃ = (0; 10), stranice platforme B₁B₂ = 17,04, B₂B₃ = 16,54, B₃B₁ = 20,84. Pri dužinama šipki 14,98; 15,38 i 12 njegova direktna kinematika ima šest realnih rešenja.</translation>
    </message>
    <message>
        <source>Planar parallel: a symmetric 3-R̲RR</source>
        <translation>Ravanski paralelni: simetrični 3-R̲RR</translation>
    </message>
    <message>
        <source>A symmetric 3-R̲RR chosen for PKM Studio, of the kind Gosselin and Angeles optimised (The optimum kinematic design of a planar three-degree-of-freedom parallel manipulator, 1988): base joints on an equilateral triangle of side 400 mm, cranks 120 mm, distal links 150 mm, an equilateral platform of circumradius 50 mm, every elbow left of A→P.</source>
        <translation>Simetrični 3-R̲RR izabran za PKM Studio, one vrste koju su optimizovali Goselen i Anđeles (članak o optimalnoj kinematičkoj sintezi ravanskog paralelnog manipulatora sa tri stepena slobode, 1988): zglobovi osnove u temenima jednakostraničnog trougla stranice 400 mm, poluge 120 mm, distalne spojke 150 mm, jednakostranična platforma poluprečnika opisanog kruga 50 mm, svaki lakat levo od A→P.</translation>
    </message>
    <message>
        <source>Planar parallel: a 5R driven by two П-joints</source>
        <translation>Ravanski paralelni: 5R pogonjen sa dva P-zgloba</translation>
    </message>
    <message>
        <source>The planar 5R of the П-joint document&apos;s fig. 5 (Milutinović, Kokotović, Slavković and Živanović), each crank the crank of a laboratory П-joint (a = 170 mm, k = 0.4, θ = ±60°, diagonal 116.2 to 231.4 mm): pivots A₁ = (0, 0) and A₂ = (200, 0) mm, the П-joints&apos; bases turned by α = ±30°, distal links 200 mm.</source>
        <translation>Ravanski 5R sa sl. 5 dokumenta o P-zglobu (Milutinović, Kokotović, Slavković i Živanović), čija je svaka poluga poluga laboratorijskog P-zgloba (a = 170 mm, k = 0.4, θ = ±60°, dijagonala od 116.2 do 231.4 mm): oslonci A₁ = (0, 0) i A₂ = (200, 0) mm, osnove P-zglobova zakrenute za α = ±30°, distalne spojke 200 mm.</translation>
    </message>
    <message>
        <source>Planar parallel: the five-bar example from two R̲RR legs</source>
        <translation>Ravanski paralelni: primer petočlanog mehanizma od dve noge R̲RR</translation>
    </message>
    <message>
        <source>The five-bar example rebuilt from the leg library (the four-bar and mobility document of Khabibullina, Khabibullin and Islamov, fig. 1): two R̲RR legs from A₁ = (0, 0) and A₂ = (100, 0) mm, cranks 80 mm, distal links 120 mm, elbows out, the platform point above the elbows. Its poses and Jacobians are the five-bar kind&apos;s.</source>
        <translation>Primer petočlanog mehanizma sastavljen iz biblioteke nogu (dokument o zglobnom četvorouglu i pokretljivosti Habibuline, Habibulina i Islamova, sl. 1): dve noge R̲RR od A₁ = (0, 0) i A₂ = (100, 0) mm, poluge 80 mm, distalne spojke 120 mm, laktovi ka spolja, tačka platforme iznad laktova. Njegove poze i Jakobijeve matrice iste su kao kod vrste petočlanog mehanizma.</translation>
    </message>
    <message>
        <source>Planar parallel: a translating platform driven by two П-joints</source>
        <translation>Ravanski paralelni: translatorna platforma pogonjena sa dva P-zgloba</translation>
    </message>
    <message>
        <source>The 2-DOF planar mechanism with a platform of constant orientation that Milutinović, Kokotović, Slavković and Živanović show among the applications of the П-joint (Механизам активног П-зглоба као еквивалента комбинације обртног зглоба и сегмента константне дужине, University of Belgrade, Faculty of Mechanical Engineering, 2014): two laboratory П-joints (a = 170 mm, k = 0.4, diagonal 116.5 to 231 mm) with their cranks at A₁ = (0, 0) and A₂ = (200, 0) mm and their bases turned by α = ±30°. The coupler of a П-joint keeps its direction, so a distal parallelogram of 200 mm from each coupler to the platform points B₁ = (−40, 0) and B₂ = (40, 0) mm keeps the platform&apos;s orientation. The second parallelogram repeats the first one&apos;s constraint: Chebyshev&apos;s count gives 1, the mobility is 2.</source>
        <translation>Ravanski mehanizam sa dva stepena slobode i platformom stalne orijentacije koji Milutinović, Kokotović, Slavković i Živanović prikazuju među primenama P-zgloba („Mehanizam aktivnog P-zgloba kao ekvivalenta kombinacije obrtnog zgloba i segmenta konstantne dužine”, Univerzitet u Beogradu, Mašinski fakultet, 2014): dva laboratorijska P-zgloba (a = 170 mm, k = 0,4, dijagonala od 116,5 do 231 mm) sa polugama u A₁ = (0, 0) i A₂ = (200, 0) mm i osnovama zakrenutim za α = ±30°. Spojka P-zgloba zadržava svoj pravac, pa distalni paralelogram od 200 mm od svake spojke do tačaka platforme B₁ = (−40, 0) i B₂ = (40, 0) mm zadržava orijentaciju platforme. Drugi paralelogram ponavlja vezu prvog: Čebiševljeva formula daje 1, a pokretljivost je 2.</translation>
    </message>
    <message>
        <source>Planar parallel: a symmetric 3-P̲RR</source>
        <translation>Ravanski paralelni: simetrični 3-P̲RR</translation>
    </message>
    <message>
        <source>A symmetric 3-P̲RR chosen for PKM Studio: three sliders driven along the sides of an equilateral triangle of side 346.41 mm (its corners A₁, A₂, A₃ 200 mm from the centre, each guide from Aᵢ towards the next corner, stroke 0 to 346.41 mm), distal links of 150 mm and an equilateral platform of circumradius 40 mm, every slider beyond the foot of the perpendicular from its platform point (working mode +1).</source>
        <translation>Simetrični 3-P̲RR izabran za PKM Studio: tri klizača pogonjena duž stranica jednakostraničnog trougla stranice 346.41 mm (njegova temena A₁, A₂, A₃ na 200 mm od centra, svaka vođica od Aᵢ ka sledećem temenu, hod od 0 do 346.41 mm), distalne spojke od 150 mm i jednakostranična platforma poluprečnika opisane kružnice 40 mm, svaki klizač iza podnožja normale iz svoje tačke platforme (radni režim +1).</translation>
    </message>
</context>
</TS>
