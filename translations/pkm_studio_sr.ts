<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="sr_RS">
<context>
    <name>QAbstractSpinBox</name>
    <message>
        <source>Step &amp;down</source>
        <translation>Корак на&amp;доле</translation>
    </message>
    <message>
        <source>&amp;Step up</source>
        <translation>Корак на&amp;горе</translation>
    </message>
    <message>
        <source>&amp;Select All</source>
        <translation>&amp;Изабери све</translation>
    </message>
</context>
<context>
    <name>QDockWidget</name>
    <message>
        <source>Close</source>
        <translation>Затвори</translation>
    </message>
    <message>
        <source>Float</source>
        <translation>Одвоји</translation>
    </message>
    <message>
        <source>Undocks and re-attaches the dock widget</source>
        <translation>Одваја панел и враћа га на место</translation>
    </message>
    <message>
        <source>Closes the dock widget</source>
        <translation>Затвара панел</translation>
    </message>
</context>
<context>
    <name>QFileDialog</name>
    <message>
        <source>Back</source>
        <translation>Назад</translation>
    </message>
    <message>
        <source>File</source>
        <translation>Датотека</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Отвори</translation>
    </message>
    <message>
        <source>&amp;Open</source>
        <translation>&amp;Отвори</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Сачувај</translation>
    </message>
    <message>
        <source>Alias</source>
        <translation>Алијас</translation>
    </message>
    <message>
        <source>Drive</source>
        <translation>Диск</translation>
    </message>
    <message>
        <source>Files</source>
        <translation>Датотеке</translation>
    </message>
    <message>
        <source>Show </source>
        <translation>Прикажи </translation>
    </message>
    <message>
        <source>&apos;%1&apos; is write protected.
Do you want to delete it anyway?</source>
        <translation>„%1“ је заштићена од уписа.
Да ли ипак желите да је обришете?</translation>
    </message>
    <message>
        <source>Are you sure you want to delete &apos;%1&apos;?</source>
        <translation>Да ли сигурно желите да обришете „%1“?</translation>
    </message>
    <message>
        <source>List of places and bookmarks</source>
        <translation>Списак места и обележивача</translation>
    </message>
    <message>
        <source>File &amp;name:</source>
        <translation>&amp;Име датотеке:</translation>
    </message>
    <message>
        <source>File Folder</source>
        <translation>Фасцикла</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Обриши</translation>
    </message>
    <message>
        <source>New Folder</source>
        <translation>Нова фасцикла</translation>
    </message>
    <message>
        <source>Folder</source>
        <translation>Фасцикла</translation>
    </message>
    <message>
        <source>Parent Directory</source>
        <translation>Надређена фасцикла</translation>
    </message>
    <message>
        <source>&amp;New Folder</source>
        <translation>&amp;Нова фасцикла</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Уклони</translation>
    </message>
    <message>
        <source>My Computer</source>
        <translation>Мој рачунар</translation>
    </message>
    <message>
        <source>Look in:</source>
        <translation>Фасцикла:</translation>
    </message>
    <message>
        <source>Create a New Folder</source>
        <translation>Направи нову фасциклу</translation>
    </message>
    <message>
        <source>%1 File</source>
        <translation>%1 датотека</translation>
    </message>
    <message>
        <source>Files of type:</source>
        <translation>Врста датотека:</translation>
    </message>
    <message>
        <source>Find Directory</source>
        <translation>Избор фасцикле</translation>
    </message>
    <message>
        <source>Show &amp;hidden files</source>
        <translation>Прикажи &amp;скривене датотеке</translation>
    </message>
    <message>
        <source>Save As</source>
        <translation>Сачувај као</translation>
    </message>
    <message>
        <source>%1
Directory not found.
Please verify the correct directory name was given.</source>
        <translation>%1
Фасцикла није пронађена.
Проверите да ли је име фасцикле тачно.</translation>
    </message>
    <message>
        <source>Sidebar</source>
        <translation>Бочна трака</translation>
    </message>
    <message>
        <source>List View</source>
        <translation>Списак</translation>
    </message>
    <message>
        <source>&amp;Choose</source>
        <translation>&amp;Изабери</translation>
    </message>
    <message>
        <source>&amp;Delete</source>
        <translation>&amp;Обриши</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Све датотеке (*)</translation>
    </message>
    <message>
        <source>All Files (*)</source>
        <translation>Све датотеке (*)</translation>
    </message>
    <message>
        <source>Directories</source>
        <translation>Фасцикле</translation>
    </message>
    <message>
        <source>&amp;Rename</source>
        <translation>&amp;Преименуј</translation>
    </message>
    <message>
        <source>Could not delete directory.</source>
        <translation>Фасцикла није могла да се обрише.</translation>
    </message>
    <message>
        <source>Directory:</source>
        <translation>Фасцикла:</translation>
    </message>
    <message>
        <source>Unknown</source>
        <translation>Непознато</translation>
    </message>
    <message>
        <source>%1 already exists.
Do you want to replace it?</source>
        <translation>%1 већ постоји.
Да ли желите да је замените?</translation>
    </message>
    <message>
        <source>Forward</source>
        <translation>Напред</translation>
    </message>
    <message>
        <source>Go forward</source>
        <translation>Иди напред</translation>
    </message>
    <message>
        <source>Go to the parent directory</source>
        <translation>Иди у надређену фасциклу</translation>
    </message>
    <message>
        <source>Recent Places</source>
        <translation>Недавна места</translation>
    </message>
    <message>
        <source>Go back</source>
        <translation>Иди назад</translation>
    </message>
    <message>
        <source>Change to detail view mode</source>
        <translation>Пређи на детаљан приказ</translation>
    </message>
    <message>
        <source>Create New Folder</source>
        <translation>Направи фасциклу</translation>
    </message>
    <message>
        <source>Shortcut</source>
        <translation>Пречица</translation>
    </message>
    <message>
        <source>Detail View</source>
        <translation>Детаљан приказ</translation>
    </message>
    <message>
        <source>%1
File not found.
Please verify the correct file name was given.</source>
        <translation>%1
Датотека није пронађена.
Проверите да ли је име датотеке тачно.</translation>
    </message>
    <message>
        <source>Change to list view mode</source>
        <translation>Пређи на приказ у облику списка</translation>
    </message>
</context>
<context>
    <name>QFileSystemModel</name>
    <message>
        <source>Kind</source>
        <translation>Врста</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Име</translation>
    </message>
    <message>
        <source>Size</source>
        <translation>Величина</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>Тип</translation>
    </message>
    <message>
        <source>My Computer</source>
        <translation>Мој рачунар</translation>
    </message>
    <message>
        <source>Computer</source>
        <translation>Рачунар</translation>
    </message>
    <message>
        <source>Invalid filename</source>
        <translation>Неисправно име датотеке</translation>
    </message>
    <message>
        <source>&lt;b&gt;The name &quot;%1&quot; cannot be used.&lt;/b&gt;&lt;p&gt;Try using another name, with fewer characters or no punctuation marks.</source>
        <translation>&lt;b&gt;Име „%1“ не може да се употреби.&lt;/b&gt;&lt;p&gt;Покушајте са другим именом, краћим или без знакова интерпункције.</translation>
    </message>
    <message>
        <source>Date Modified</source>
        <translation>Измењено</translation>
    </message>
</context>
<context>
    <name>QGnomeTheme</name>
    <message>
        <source>&amp;OK</source>
        <translation>&amp;У реду</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Сачувај</translation>
    </message>
    <message>
        <source>&amp;Close</source>
        <translation>&amp;Затвори</translation>
    </message>
    <message>
        <source>Close without Saving</source>
        <translation>Затвори без чувања</translation>
    </message>
    <message>
        <source>&amp;Cancel</source>
        <translation>&amp;Откажи</translation>
    </message>
</context>
<context>
    <name>QLineEdit</name>
    <message>
        <source>Cu&amp;t</source>
        <translation>Исе&amp;ци</translation>
    </message>
    <message>
        <source>&amp;Copy</source>
        <translation>&amp;Копирај</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Понови</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Опозови</translation>
    </message>
    <message>
        <source>&amp;Paste</source>
        <translation>&amp;Налепи</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Обриши</translation>
    </message>
    <message>
        <source>Select All</source>
        <translation>Изабери све</translation>
    </message>
</context>
<context>
    <name>QPlatformTheme</name>
    <message>
        <source>OK</source>
        <translation>У реду</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Сачувај</translation>
    </message>
    <message>
        <source>Save All</source>
        <translation>Сачувај све</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Отвори</translation>
    </message>
    <message>
        <source>&amp;Yes</source>
        <translation>&amp;Да</translation>
    </message>
    <message>
        <source>Yes to &amp;All</source>
        <translation>Да за &amp;све</translation>
    </message>
    <message>
        <source>&amp;No</source>
        <translation>&amp;Не</translation>
    </message>
    <message>
        <source>N&amp;o to All</source>
        <translation>Н&amp;е за све</translation>
    </message>
    <message>
        <source>Abort</source>
        <translation>Прекини</translation>
    </message>
    <message>
        <source>Retry</source>
        <translation>Покушај поново</translation>
    </message>
    <message>
        <source>Ignore</source>
        <translation>Занемари</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Затвори</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Откажи</translation>
    </message>
    <message>
        <source>Discard</source>
        <translation>Одбаци</translation>
    </message>
    <message>
        <source>Help</source>
        <translation>Помоћ</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Примени</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Поништи</translation>
    </message>
    <message>
        <source>Restore Defaults</source>
        <translation>Врати подразумевано</translation>
    </message>
</context>
<context>
    <name>QScrollBar</name>
    <message>
        <source>Top</source>
        <translation>На врх</translation>
    </message>
    <message>
        <source>Scroll down</source>
        <translation>Помери надоле</translation>
    </message>
    <message>
        <source>Scroll here</source>
        <translation>Помери овде</translation>
    </message>
    <message>
        <source>Scroll left</source>
        <translation>Помери улево</translation>
    </message>
    <message>
        <source>Bottom</source>
        <translation>На дно</translation>
    </message>
    <message>
        <source>Page up</source>
        <translation>Страна нагоре</translation>
    </message>
    <message>
        <source>Page right</source>
        <translation>Страна удесно</translation>
    </message>
    <message>
        <source>Scroll up</source>
        <translation>Помери нагоре</translation>
    </message>
    <message>
        <source>Scroll right</source>
        <translation>Помери удесно</translation>
    </message>
    <message>
        <source>Left edge</source>
        <translation>До леве ивице</translation>
    </message>
    <message>
        <source>Page down</source>
        <translation>Страна надоле</translation>
    </message>
    <message>
        <source>Page left</source>
        <translation>Страна улево</translation>
    </message>
    <message>
        <source>Right edge</source>
        <translation>До десне ивице</translation>
    </message>
</context>
<context>
    <name>QTabBar</name>
    <message>
        <source>Scroll Left</source>
        <translation>Помери улево</translation>
    </message>
    <message>
        <source>Scroll Right</source>
        <translation>Помери удесно</translation>
    </message>
</context>
<context>
    <name>QWidgetTextControl</name>
    <message>
        <source>Cu&amp;t</source>
        <translation>Исе&amp;ци</translation>
    </message>
    <message>
        <source>&amp;Copy</source>
        <translation>&amp;Копирај</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Понови</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Опозови</translation>
    </message>
    <message>
        <source>&amp;Paste</source>
        <translation>&amp;Налепи</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Обриши</translation>
    </message>
    <message>
        <source>Select All</source>
        <translation>Изабери све</translation>
    </message>
    <message>
        <source>Copy &amp;Link Location</source>
        <translation>Копирај &amp;адресу везе</translation>
    </message>
</context>
<context>
    <name>Sheet</name>
    <message>
        <source>frame</source>
        <translation>постоље</translation>
    </message>
    <message>
        <source>crank</source>
        <translation>полуга</translation>
    </message>
    <message>
        <source>coupler</source>
        <translation>спојка</translation>
    </message>
    <message>
        <source>link</source>
        <translation>члан</translation>
    </message>
    <message>
        <source>rod</source>
        <translation>шипка</translation>
    </message>
    <message>
        <source>platform</source>
        <translation>платформа</translation>
    </message>
    <message>
        <source>Design parameters</source>
        <translation>Параметри конструкције</translation>
    </message>
    <message>
        <source> (derived)</source>
        <translation> (изведена величина)</translation>
    </message>
    <message>
        <source>Derived dimensions</source>
        <translation>Изведене мере</translation>
    </message>
    <message>
        <source>Links and guides (between joint centres)</source>
        <translation>Чланови и вођице (између средишта зглобова)</translation>
    </message>
    <message>
        <source>between</source>
        <translation>између</translation>
    </message>
    <message>
        <source>part</source>
        <translation>део</translation>
    </message>
    <message>
        <source>kind</source>
        <translation>врста</translation>
    </message>
    <message>
        <source>length</source>
        <translation>дужина</translation>
    </message>
    <message>
        <source>guide</source>
        <translation>вођица</translation>
    </message>
    <message>
        <source>guide (stroke)</source>
        <translation>вођица (ход)</translation>
    </message>
    <message>
        <source>Ranges of motion</source>
        <translation>Опсези кретања</translation>
    </message>
    <message>
        <source>variable</source>
        <translation>променљива</translation>
    </message>
    <message>
        <source>role</source>
        <translation>улога</translation>
    </message>
    <message>
        <source>this pose</source>
        <translation>овај положај</translation>
    </message>
    <message>
        <source>min</source>
        <translation>мин</translation>
    </message>
    <message>
        <source>max</source>
        <translation>макс</translation>
    </message>
    <message>
        <source>travel</source>
        <translation>ход</translation>
    </message>
    <message>
        <source>unit</source>
        <translation>јединица</translation>
    </message>
    <message>
        <source>input (actuated)</source>
        <translation>улаз (погонски)</translation>
    </message>
    <message>
        <source>output</source>
        <translation>излаз</translation>
    </message>
    <message>
        <source>pose</source>
        <translation>положај</translation>
    </message>
    <message>
        <source>home</source>
        <translation>почетни положај</translation>
    </message>
    <message>
        <source>%1 max</source>
        <translation>%1 макс</translation>
    </message>
    <message>
        <source>%1 min</source>
        <translation>%1 мин</translation>
    </message>
    <message>
        <source>Every actuated input at the ends of its range with the others at the home pose, where the mechanism reaches it.</source>
        <translation>Сваки погонски улаз на крајевима свог опсега, док су остали у почетном положају — где механизам може да достигне тај положај.</translation>
    </message>
    <message>
        <source>No singular pose in the range of motion</source>
        <translation>Нема сингуларних положаја у опсегу кретања</translation>
    </message>
    <message>
        <source>singularity margin ≥ %1</source>
        <translation>маргина сингуларитета ≥ %1</translation>
    </message>
    <message>
        <source>least at %1 = %2</source>
        <translation>најмања при %1 = %2</translation>
    </message>
    <message>
        <source>%1 over %2</source>
        <translation>%1 у зависности од %2</translation>
    </message>
    <message>
        <source>Dimensioned drawing</source>
        <translation>Котирани цртеж</translation>
    </message>
    <message>
        <source>The mechanism in the pose of this sheet, scale %1</source>
        <translation>Механизам у положају ове листе, размера %1</translation>
    </message>
    <message>
        <source>Pose: %1. Scale %2 on A4 (the scale bar holds on any print size). Lengths in mm, angles in degrees; the dimensions are those of the pose shown.</source>
        <translation>Положај: %1. Размера %2 на формату A4 (графичка размера важи при свакој величини штампе). Дужине у mm, углови у степенима; мере важе за приказани положај.</translation>
    </message>
    <message>
        <source>Design warnings</source>
        <translation>Упозорења о конструкцији</translation>
    </message>
    <message>
        <source>Key poses</source>
        <translation>Карактеристични положаји</translation>
    </message>
    <message>
        <source>Checks</source>
        <translation>Провере</translation>
    </message>
    <message>
        <source>Plots</source>
        <translation>Дијаграми</translation>
    </message>
    <message>
        <source>screw beyond the motor body at d_min</source>
        <translation>део вретена изван тела мотора при d_min</translation>
    </message>
    <message>
        <source>screw beyond the motor body at d_max (least free screw length)</source>
        <translation>део вретена изван тела мотора при d_max (најмања слободна дужина вретена)</translation>
    </message>
    <message>
        <source>motor steps per revolution of the screw</source>
        <translation>корака мотора по обртају вретена</translation>
    </message>
    <message>
        <source>motor speed at ḋ_max, 60·ḋ_max/h</source>
        <translation>број обртаја мотора при ḋ_max, 60·ḋ_max/h</translation>
    </message>
    <message>
        <source>step rate at ḋ_max, ḋ_max/Δd</source>
        <translation>учестаност корака при ḋ_max, ḋ_max/Δd</translation>
    </message>
    <message>
        <source>Key poses over the range and the recommended range</source>
        <translation>Карактеристични положаји: опсег кретања и препоручени опсег</translation>
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
        <translation> (овај положај)</translation>
    </message>
    <message>
        <source>T at F_max = %1 N, θ̇ at ḋ_max = %2 mm/s, Δθ per motor step Δd = %3 mm. The recommended range keeps J — and with it T, θ̇ and Δθ — within %4 % of its best over the range (the document: θ = −60°…40°).</source>
        <translation>T при F_max = %1 N, θ̇ при ḋ_max = %2 mm/s, Δθ по кораку мотора Δd = %3 mm. У препорученом опсегу J — а с њим и T, θ̇ и Δθ — остаје у границама од %4 % своје најбоље вредности у опсегу (у документу: θ = −60°…40°).</translation>
    </message>
    <message>
        <source>Actuator check</source>
        <translation>Провера актуатора</translation>
    </message>
    <message>
        <source>The chosen motor: lead h = %1 mm, step Δd = %2 mm, ḋ_max = %3 mm/s, thrust F_max = %4 N, screw efficiency η = %5; body %6 mm long.</source>
        <translation>Изабрани мотор: успон навоја h = %1 mm, корак Δd = %2 mm, ḋ_max = %3 mm/s, потисна сила F_max = %4 N, степен искоришћења вретена η = %5; дужина тела %6 mm.</translation>
    </message>
    <message>
        <source>Motor body fits the shortest diagonal</source>
        <translation>Тело мотора стаје у најкраћу дијагоналу</translation>
    </message>
    <message>
        <source>stroke d_max − d_min = %1 mm</source>
        <translation>ход d_max − d_min = %1 mm</translation>
    </message>
    <message>
        <source>worst at θ = %1, best at θ = %2; recommended range %3…%4</source>
        <translation>најлошије при θ = %1, најбоље при θ = %2; препоручени опсег %3…%4</translation>
    </message>
    <message>
        <source>Output torque T = J·F_max (13)</source>
        <translation>Излазни момент T = J·F_max (13)</translation>
    </message>
    <message>
        <source>least T ≥ %1 % of the best</source>
        <translation>најмањи T ≥ %1 % од највећег</translation>
    </message>
    <message>
        <source>Output speed θ̇ = ḋ_max/J (8)</source>
        <translation>Излазна брзина θ̇ = ḋ_max/J (8)</translation>
    </message>
    <message>
        <source>greatest θ̇ ≤ the least ÷ %1</source>
        <translation>највећа θ̇ ≤ најмања ÷ %1</translation>
    </message>
    <message>
        <source>Output resolution Δθ = Δd/J</source>
        <translation>Излазна резолуција Δθ = Δd/J</translation>
    </message>
    <message>
        <source>coarsest Δθ ≤ the finest ÷ %1</source>
        <translation>најгрубље Δθ ≤ најфиније ÷ %1</translation>
    </message>
    <message>
        <source>No singular pose in the range (θ = ±90°)</source>
        <translation>Нема сингуларних положаја у опсегу (θ = ±90°)</translation>
    </message>
    <message>
        <source>|cos θ| ≥ %1</source>
        <translation>|cos θ| ≥ %1</translation>
    </message>
    <message>
        <source>Motor torque to push F_max</source>
        <translation>Момент мотора потребан за силу F_max</translation>
    </message>
    <message>
        <source>the motor must give it at %1 min⁻¹ (%2 steps/s)</source>
        <translation>мотор мора да га даје при %1 min⁻¹ (%2 корака/s)</translation>
    </message>
    <message>
        <source>FAIL above means that the range of θ reaches where J falls steeply: keep the joint in the recommended range %1…%2 where it must give its torque, speed and resolution.</source>
        <translation>„НИЈЕ ИСПУЊЕНО“ изнад значи да опсег θ залази у област наглог пада J: тамо где зглоб мора да даје свој момент, брзину и резолуцију, држите га у препорученом опсегу %1…%2.</translation>
    </message>
    <message>
        <source>Diagonal length d(θ) (2), fig. 8</source>
        <translation>Дужина дијагонале d(θ) (2), сл. 8</translation>
    </message>
    <message>
        <source>Transmission angle μ(θ), fig. 10</source>
        <translation>Угао преноса μ(θ), сл. 10</translation>
    </message>
    <message>
        <source>Jacobian J(θ) = ∂d/∂θ (7), fig. 11</source>
        <translation>Јакобијан J(θ) = ∂d/∂θ (7), сл. 11</translation>
    </message>
    <message>
        <source>Output torque T = J·F_max (13), fig. 17</source>
        <translation>Излазни момент T = J·F_max (13), сл. 17</translation>
    </message>
    <message>
        <source>Output speed θ̇ = ḋ_max/J, fig. 16</source>
        <translation>Излазна брзина θ̇ = ḋ_max/J, сл. 16</translation>
    </message>
    <message>
        <source>Output resolution Δθ = Δd/J, fig. 15</source>
        <translation>Излазна резолуција Δθ = Δd/J, сл. 15</translation>
    </message>
    <message>
        <source>θ (°)</source>
        <translation>θ (°)</translation>
    </message>
    <message>
        <source>beyond the θ range</source>
        <translation>изван опсега θ</translation>
    </message>
    <message>
        <source>this design (k = %1)</source>
        <translation>ова конструкција (k = %1)</translation>
    </message>
    <message>
        <source>recommended range</source>
        <translation>препоручени опсег</translation>
    </message>
    <message>
        <source>steep region</source>
        <translation>стрма област</translation>
    </message>
    <message>
        <source>a = %1 mm; the family k = 0.3 … 1.5 at the same a</source>
        <translation>a = %1 mm; фамилија k = 0,3 … 1,5 при истом a</translation>
    </message>
    <message>
        <source>crank-rocker</source>
        <translation>полуга–клацкалица</translation>
    </message>
    <message>
        <source>rocker-crank</source>
        <translation>клацкалица–полуга</translation>
    </message>
    <message>
        <source>double-crank</source>
        <translation>двострука полуга</translation>
    </message>
    <message>
        <source>double-rocker</source>
        <translation>двострука клацкалица</translation>
    </message>
    <message>
        <source>triple-rocker (non-Grashof)</source>
        <translation>трострука клацкалица (није по Грасхофу)</translation>
    </message>
    <message>
        <source>change-point</source>
        <translation>прелазни</translation>
    </message>
    <message>
        <source>class</source>
        <translation>класа</translation>
    </message>
    <message>
        <source>Grashof class, s + l against p + q</source>
        <translation>класа по Грасхофу: s + l у односу на p + q</translation>
    </message>
    <message>
        <source>shortest + longest link</source>
        <translation>најкраћи + најдужи члан</translation>
    </message>
    <message>
        <source>the other two links</source>
        <translation>друга два члана</translation>
    </message>
    <message>
        <source>Key poses over the crank angle</source>
        <translation>Карактеристични положаји по углу полуге</translation>
    </message>
    <message>
        <source>least μ</source>
        <translation>најмањи μ</translation>
    </message>
    <message>
        <source>At the constant crank speed ω₁ = %1 rad/s.</source>
        <translation>При сталној угаоној брзини полуге ω₁ = %1 rad/s.</translation>
    </message>
    <message>
        <source>Design check</source>
        <translation>Провера конструкције</translation>
    </message>
    <message>
        <source>Grashof class</source>
        <translation>Класа по Грасхофу</translation>
    </message>
    <message>
        <source>s + l = %1 mm, p + q = %2 mm</source>
        <translation>s + l = %1 mm; p + q = %2 mm</translation>
    </message>
    <message>
        <source>Crank angle range</source>
        <translation>Опсег угла полуге</translation>
    </message>
    <message>
        <source>the crank AB turns fully</source>
        <translation>полуга AB се обрће пун круг</translation>
    </message>
    <message>
        <source>the crank AB cannot turn fully</source>
        <translation>полуга AB не може да се обрне пун круг</translation>
    </message>
    <message>
        <source>Least transmission angle over the range</source>
        <translation>Најмањи угао преноса у опсегу</translation>
    </message>
    <message>
        <source>at α = %1°</source>
        <translation>при α = %1°</translation>
    </message>
    <message>
        <source>Rocker angle δ(α)</source>
        <translation>Угао клацкалице δ(α)</translation>
    </message>
    <message>
        <source>Transmission angle μ(α)</source>
        <translation>Угао преноса μ(α)</translation>
    </message>
    <message>
        <source>Rocker angular velocity ω₃(α)</source>
        <translation>Угаона брзина клацкалице ω₃(α)</translation>
    </message>
    <message>
        <source>Rocker angular acceleration ε₃(α)</source>
        <translation>Угаоно убрзање клацкалице ε₃(α)</translation>
    </message>
    <message>
        <source>μ = %1°: poor below</source>
        <translation>μ = %1°: испод тога лош пренос</translation>
    </message>
    <message>
        <source>none</source>
        <translation>нема</translation>
    </message>
    <message>
        <source>inverse</source>
        <translation>инверзни</translation>
    </message>
    <message>
        <source>direct</source>
        <translation>директни</translation>
    </message>
    <message>
        <source>combined</source>
        <translation>комбиновани</translation>
    </message>
    <message>
        <source>PASS</source>
        <translation>ИСПУЊЕНО</translation>
    </message>
    <message>
        <source>FAIL</source>
        <translation>НИЈЕ ИСПУЊЕНО</translation>
    </message>
    <message>
        <source>INFO</source>
        <translation>ИНФО</translation>
    </message>
    <message>
        <source>singularity</source>
        <translation>сингуларитет</translation>
    </message>
    <message>
        <source>singularity class of the pose</source>
        <translation>врста сингуларитета у том положају</translation>
    </message>
    <message>
        <source>PKM Studio · Parameter sheet</source>
        <translation>PKM Studio · Листа параметара</translation>
    </message>
    <message>
        <source>page %1 of %2</source>
        <translation>страна %1 од %2</translation>
    </message>
    <message>
        <source>Parameter sheet</source>
        <translation>Листа параметара</translation>
    </message>
    <message>
        <source>field</source>
        <translation>поље</translation>
    </message>
    <message>
        <source>value</source>
        <translation>вредност</translation>
    </message>
    <message>
        <source>Design</source>
        <translation>Конструкција</translation>
    </message>
    <message>
        <source>Mechanism</source>
        <translation>Механизам</translation>
    </message>
    <message>
        <source>Pose</source>
        <translation>Положај</translation>
    </message>
    <message>
        <source>Date</source>
        <translation>Датум</translation>
    </message>
    <message>
        <source>Software</source>
        <translation>Програм</translation>
    </message>
    <message>
        <source>About</source>
        <translation>Опис</translation>
    </message>
    <message>
        <source>Units: lengths mm, angles degrees, forces N, torques N·m, times s, unless a column says otherwise.</source>
        <translation>Јединице: дужине у mm, углови у степенима, силе у N, моменти у N·m, време у s, осим ако у колони не пише другачије.</translation>
    </message>
    <message>
        <source>Geometry</source>
        <translation>Геометрија</translation>
    </message>
    <message>
        <source>Range of motion</source>
        <translation>Опсег кретања</translation>
    </message>
    <message>
        <source>Actuator</source>
        <translation>Актуатор</translation>
    </message>
    <message>
        <source>Drawing only</source>
        <translation>Само за цртеж</translation>
    </message>
    <message>
        <source>Working and assembly modes</source>
        <translation>Радни режими и начини склапања</translation>
    </message>
    <message>
        <source>symbol</source>
        <translation>ознака</translation>
    </message>
    <message>
        <source>quantity</source>
        <translation>величина</translation>
    </message>
    <message>
        <source>key</source>
        <translation>кључ</translation>
    </message>
    <message>
        <source>check</source>
        <translation>провера</translation>
    </message>
    <message>
        <source>limit</source>
        <translation>граница</translation>
    </message>
    <message>
        <source>result</source>
        <translation>резултат</translation>
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
        <translation>размера (A4)</translation>
    </message>
    <message>
        <source>scale bar</source>
        <translation>графичка размера</translation>
    </message>
    <message>
        <source>units</source>
        <translation>јединице</translation>
    </message>
    <message>
        <source>mm, degrees</source>
        <translation>mm, степени</translation>
    </message>
    <message>
        <source>design</source>
        <translation>конструкција</translation>
    </message>
    <message>
        <source>date</source>
        <translation>датум</translation>
    </message>
    <message>
        <source>Parameter sheet: %1</source>
        <translation>Листа параметара: %1</translation>
    </message>
    <message>
        <source>Workspace</source>
        <translation>Радни простор</translation>
    </message>
    <message>
        <source>The platform positions reachable with every actuated input inside its range%1, on a grid of %2 × %3 square cells of %4 mm (as &apos;pkm workspace --grid %5&apos;).</source>
        <translation>Положаји платформе достижни када је сваки погонски улаз унутар свог опсега%1, на мрежи од %2 × %3 квадратних ћелија странице %4 mm (као &apos;pkm workspace --grid %5&apos;).</translation>
    </message>
    <message>
        <source>area of this form&apos;s workspace (exact)</source>
        <translation>површина радног простора овог облика (тачно)</translation>
    </message>
    <message>
        <source>area of the extended (O) form (exact)</source>
        <translation>површина за опружени (O) облик (тачно)</translation>
    </message>
    <message>
        <source>area of the crossed (X) form (exact)</source>
        <translation>површина за укрштени (X) облик (тачно)</translation>
    </message>
    <message>
        <source>area of this form on the grid</source>
        <translation>површина овог облика на мрежи</translation>
    </message>
    <message>
        <source>area of the workspace (grid)</source>
        <translation>површина радног простора (по мрежи)</translation>
    </message>
    <message>
        <source>area in mode %1 (grid)</source>
        <translation>површина у режиму %1 (по мрежи)</translation>
    </message>
    <message>
        <source>area of the union of all modes (grid)</source>
        <translation>површина уније свих режима (по мрежи)</translation>
    </message>
    <message>
        <source>travel of the carrying axis</source>
        <translation>ход носеће осе</translation>
    </message>
    <message>
        <source>volume: the area extruded over the travel</source>
        <translation>запремина: површина извучена дуж хода</translation>
    </message>
    <message>
        <source>reachable cells from x</source>
        <translation>достижне ћелије од x</translation>
    </message>
    <message>
        <source>reachable cells to x</source>
        <translation>достижне ћелије до x</translation>
    </message>
    <message>
        <source>reachable cells from y</source>
        <translation>достижне ћелије од y</translation>
    </message>
    <message>
        <source>reachable cells to y</source>
        <translation>достижне ћелије до y</translation>
    </message>
    <message>
        <source>cells</source>
        <translation>ћелије</translation>
    </message>
    <message>
        <source>reachable cells of the grid</source>
        <translation>достижне ћелије мреже</translation>
    </message>
    <message>
        <source>Area per working and assembly mode</source>
        <translation>Површина по радним режимима и начинима склапања</translation>
    </message>
    <message>
        <source>mode</source>
        <translation>мод</translation>
    </message>
    <message>
        <source>area (grid)</source>
        <translation>површина (по мрежи)</translation>
    </message>
    <message>
        <source>area (exact)</source>
        <translation>површина (тачно)</translation>
    </message>
    <message>
        <source>note</source>
        <translation>напомена</translation>
    </message>
    <message>
        <source>this design</source>
        <translation>ова конструкција</translation>
    </message>
    <message>
        <source>no workspace</source>
        <translation>нема радног простора</translation>
    </message>
    <message>
        <source>Workspaces of the modes</source>
        <translation>Радни простори по режимима</translation>
    </message>
    <message>
        <source>As &apos;pkm workspace -o FILE.png&apos;: this design&apos;s mode dark blue over the others&apos; light blue, the outline of their union dark.</source>
        <translation>Као &apos;pkm workspace -o FILE.png&apos;: режим ове конструкције тамноплаво преко осталих (светлоплаво), обрис њихове уније тамно.</translation>
    </message>
    <message>
        <source>As &apos;pkm workspace -o FILE.png&apos;: the reachable cells light blue with a dark outline.</source>
        <translation>Као &apos;pkm workspace -o FILE.png&apos;: достижне ћелије светлоплаво, са тамним обрисом.</translation>
    </message>
    <message>
        <source>Singularity map: det J</source>
        <translation>Мапа сингуларитета: det J</translation>
    </message>
    <message>
        <source>As &apos;pkm map -o FILE.png&apos;: det J blue below 0, white at 0 (a direct singularity), red above 0, clipped at ±%1; the inverse singular curves dark red, the direct ones dashed.</source>
        <translation>Као &apos;pkm map -o FILE.png&apos;: det J плаво испод 0, бело у 0 (директни сингуларитет), црвено изнад 0, одсечено на ±%1; инверзне сингуларне криве тамноцрвене, директне испрекидане.</translation>
    </message>
    <message>
        <source>Singular poses in the workspace</source>
        <translation>Сингуларни положаји у радном простору</translation>
    </message>
    <message>
        <source>near-singular cells (margin &lt; %1, about 3° from a singular pose)</source>
        <translation>ћелије близу сингуларитета (маргина &lt; %1, око 3° од сингуларног положаја)</translation>
    </message>
    <message>
        <source>their area</source>
        <translation>њихова површина</translation>
    </message>
    <message>
        <source>Singular curves, each with one of its poses</source>
        <translation>Сингуларне криве, свака са једним од својих положаја</translation>
    </message>
    <message>
        <source>where</source>
        <translation>где</translation>
    </message>
    <message>
        <source>type</source>
        <translation>врста</translation>
    </message>
    <message>
        <source>curve length</source>
        <translation>дужина криве</translation>
    </message>
    <message>
        <source>Inverse: a leg loses a degree of freedom (a link perpendicular to its guide); direct: the platform gains one (the links in line). The pose given is the middle of each curve.</source>
        <translation>Инверзни: кинематички ланац губи један степен слободе (члан управан на своју вођицу); директни: платформа добија један степен слободе (чланови у истој линији). Дати положај је средина сваке криве.</translation>
    </message>
    <message>
        <source>No singular curve lies inside the workspace.</source>
        <translation>Ниједна сингуларна крива не лежи унутар радног простора.</translation>
    </message>
    <message>
        <source>Stroke of %1 the workspace uses</source>
        <translation>Ход %1 који користи радни простор</translation>
    </message>
    <message>
        <source>within the guide %1 … %2</source>
        <translation>унутар вођице %1 … %2</translation>
    </message>
    <message>
        <source>within its range %1 … %2</source>
        <translation>унутар свог опсега %1 … %2</translation>
    </message>
    <message>
        <source>used from %1 to %2</source>
        <translation>користи се од %1 до %2</translation>
    </message>
    <message>
        <source>Direct singular poses in the workspace</source>
        <translation>Директни сингуларни положаји у радном простору</translation>
    </message>
    <message>
        <source>Inverse singular poses in the workspace</source>
        <translation>Инверзни сингуларни положаји у радном простору</translation>
    </message>
    <message>
        <source>none: the platform would move with the actuators locked</source>
        <translation>не сме их бити: платформа би се померала са закоченим актуаторима</translation>
    </message>
    <message>
        <source>where a leg reaches the end of its reach; keep away in use</source>
        <translation>где кинематички ланац достиже крај свог домета; у раду се држати даље од њих</translation>
    </message>
    <message>
        <source>no singular curve of this kind</source>
        <translation>нема сингуларних кривих ове врсте</translation>
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
        <translation>корака/s</translation>
    </message>
    <message>
        <source>mm³</source>
        <translation>mm³</translation>
    </message>
    <message>
        <source>Actuator capability</source>
        <translation>Могућности погона</translation>
    </message>
    <message>
        <source>What the actuators deliver at the platform at this pose, every actuator within its limits: the force and the speed in the weakest and the strongest direction, the error from half a step per actuator and the stiffness from the actuators alone.</source>
        <translation>Шта погони дају на платформи у овом положају, сваки у својим границама: сила и брзина у најслабијем и најјачем правцу, грешка од пола корака сваког погона и крутост од самих погона.</translation>
    </message>
    <message>
        <source>The actuator&apos;s axial stiffness is an assumed value (about 20 N/µm for a small lead screw with its nut and bearings): Table 1 gives none.</source>
        <translation>Аксијална крутост погона је претпостављена (око 20 Н/µм за мало навојно вретено с навртком и лежајевима): табела 1 је не даје.</translation>
    </message>
    <message>
        <source>Actuator values left at their defaults are assumed, plausible ones (a NEMA 17 stepper with a 5:1 gearbox, a small lead-screw slide): the source documents give none.</source>
        <translation>Вредности погона остављене на подразумеваним су претпостављене, уверљиве (корачни мотор NEMA 17 с редуктором 5:1, мали клизач с навојним вретеном): изворни документи их не дају.</translation>
    </message>
    <message>
        <source>The actuator alone would make the joint %1 N·m/rad stiff here; the measured %2 N·m/rad is lower because the hinges, links and frame yield in series with it (1/K = 1/K_actuator + 1/K_rest): together they are about %3 N·m/rad.</source>
        <translation>Сам погон би овде зглобу дао крутост %1 Н·м/рад; измерених %2 Н·м/рад је мање јер зглобови, чланци и рам попуштају редно с њим (1/K = 1/K_погона + 1/K_остало): заједно дају око %3 Н·м/рад.</translation>
    </message>
    <message>
        <source>The actuator alone gives %1 N·m/rad here, less than the measured %2 N·m/rad of the whole joint: the assumed axial stiffness of the actuator is too low for the measurement, or the pose is near a singularity where the actuator cannot hold the output.</source>
        <translation>Сам погон овде даје %1 Н·м/рад, мање од измерених %2 Н·м/рад целог зглоба: претпостављена аксијална крутост погона је премала за мерење, или је положај близу сингуларног, где погон не држи излаз.</translation>
    </message>
    <message>
        <source>The actuators hold the design&apos;s load at this pose</source>
        <translation>Погони држе оптерећење конструкције у овом положају</translation>
    </message>
    <message>
        <source>max |τ_i| / τ_max,i ≤ 1</source>
        <translation>max |τ_i| / τ_max,i ≤ 1</translation>
    </message>
    <message>
        <source>no load</source>
        <translation>нема оптерећења</translation>
    </message>
    <message>
        <source>The design states no load (load_x, load_y, load_moment or load_torque in the actuator group).</source>
        <translation>Конструкција не задаје оптерећење (load_x, load_y, load_moment или load_torque у групи погона).</translation>
    </message>
    <message>
        <source>actuator %1 at %2 % of its limit</source>
        <translation>погон %1 на %2 % своје границе</translation>
    </message>
    <message>
        <source>at a direct singularity no effort of the actuators holds a load</source>
        <translation>у сингуларитету директне кинематике ниједан напор погона не држи оптерећење</translation>
    </message>
    <message>
        <source>Required at this pose: %1</source>
        <translation>Захтева се у овом положају: %1</translation>
    </message>
    <message>
        <source>undefined</source>
        <translation>недефинисано</translation>
    </message>
    <message>
        <source>Every requirement holds over the whole workspace</source>
        <translation>Сви захтеви испуњени у целом радном простору</translation>
    </message>
    <message>
        <source>area met = workspace area</source>
        <translation>површина испуњења = површина радног простора</translation>
    </message>
    <message>
        <source>met in %1 mm² of %2 mm² (grid of %3 × %4 cells)</source>
        <translation>испуњени на %1 mm² од %2 mm² (мрежа од %3 × %4 ћелија)</translation>
    </message>
</context>
<context>
    <name>core</name>
    <message>
        <source>The rank counts the platform&apos;s x and y, the carriage&apos;s z and the platform&apos;s tilt (its swing about the longitudinal axis). The actuators drive x_AB, x_CD and z; the tilt is not held by them. With the joints the document describes (spherical at the platform, one hinge per rod at the slider, a pair&apos;s rods one behind the other) the platform can tilt with the sliders locked; the document&apos;s kinematics assume it stays level.</source>
        <translation>Ранг обухвата x и y платформе, z колица и нагиб платформе (њено љуљање око подужне осе). Погони задају x_AB, x_CD и z; нагиб они не држе. Са зглобовима које рад описује (сферни код платформе, по један зглоб за сваки штап код клизача, штапови једног пара један иза другог) платформа може да се нагне са закоченим клизачима; кинематика из рада претпоставља да платформа остаје водоравна.</translation>
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
        <translation>mm/обр</translation>
    </message>
    <message>
        <source>mm/step</source>
        <translation>mm/корак</translation>
    </message>
    <message>
        <source>°/step</source>
        <translation>°/корак</translation>
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
        <translation>%1 десно од %2</translation>
    </message>
    <message>
        <source>%1 left of %2</source>
        <translation>%1 лево од %2</translation>
    </message>
    <message>
        <source>length of crank 1, driven at A</source>
        <translation>дужина полуге 1 (погон у A)</translation>
    </message>
    <message>
        <source>length of distal link 1, from B to C</source>
        <translation>дужина спојке 1, од B до C</translation>
    </message>
    <message>
        <source>length of distal link 2, from C to D</source>
        <translation>дужина спојке 2, од C до D</translation>
    </message>
    <message>
        <source>length of crank 2, driven at E</source>
        <translation>дужина полуге 2 (погон у E)</translation>
    </message>
    <message>
        <source>length of the ground, from A to E along +x</source>
        <translation>дужина постоља, од A до E дуж +x</translation>
    </message>
    <message>
        <source>lower limit of crank angle θ₁</source>
        <translation>доња граница угла полуге θ₁</translation>
    </message>
    <message>
        <source>upper limit of crank angle θ₁</source>
        <translation>горња граница угла полуге θ₁</translation>
    </message>
    <message>
        <source>lower limit of crank angle θ₄</source>
        <translation>доња граница угла полуге θ₄</translation>
    </message>
    <message>
        <source>upper limit of crank angle θ₄</source>
        <translation>горња граница угла полуге θ₄</translation>
    </message>
    <message>
        <source>left</source>
        <translation>лево</translation>
    </message>
    <message>
        <source>right</source>
        <translation>десно</translation>
    </message>
    <message>
        <source>working mode of leg 1: elbow B left (+1) or right (−1) of A→C</source>
        <translation>радни режим ноге 1: зглоб B лево (+1) или десно (−1) од A→C</translation>
    </message>
    <message>
        <source>working mode of leg 2: elbow D left (+1) or right (−1) of E→C</source>
        <translation>радни режим ноге 2: зглоб D лево (+1) или десно (−1) од E→C</translation>
    </message>
    <message>
        <source>assembly mode: C left (+1) or right (−1) of B→D</source>
        <translation>начин склапања: C лево (+1) или десно (−1) од B→D</translation>
    </message>
    <message>
        <source>%1 = %2 is invalid: it must be +1 (left) or -1 (right).</source>
        <translation>%1 = %2 није дозвољена вредност: мора бити +1 (лево) или -1 (десно).</translation>
    </message>
    <message>
        <source>The five-bar linkage has no parameter named &apos;%1&apos;.</source>
        <translation>Зглобни петоугао нема параметар „%1“.</translation>
    </message>
    <message>
        <source>%1 = %2 must be less than %3 = %4.</source>
        <translation>%1 = %2 мора бити мање од %3 = %4.</translation>
    </message>
    <message>
        <source>%1 = %2 lies %3 above %4 = %5: a crank&apos;s range may span one turn (360°) at most.</source>
        <translation>%1 = %2 је за %3 изнад %4 = %5: опсег полуге може да обухвати највише један обрт (360°).</translation>
    </message>
    <message>
        <source>%1 = %2 is not shorter than %3 = %4: the links cannot close the loop ABCDE for any crank angles (each link must be shorter than the other four together).</source>
        <translation>%1 = %2 није краће од %3 = %4: чланови не могу да затворе контуру ABCDE ни за које углове полуга (сваки члан мора бити краћи од збира остала четири).</translation>
    </message>
    <message>
        <source>This five-bar has no workspace: with %1 the loop ABCDE never closes. Change a mode, a range or a length.</source>
        <translation>Овај зглобни петоугао нема радни простор: са %1 контура ABCDE се никада не затвара. Промените мод, опсег или дужину.</translation>
    </message>
    <message>
        <source>This five-bar has no workspace: with %1 and the crank ranges %2 the loop ABCDE never closes. Change a mode, a range or a length.</source>
        <translation>Овај зглобни петоугао нема радни простор: са %1 и опсезима полуга %2 контура ABCDE се никада не затвара. Промените мод, опсег или дужину.</translation>
    </message>
    <message>
        <source>The workspace of these modes reaches direct singularities (the curves where the distal links BC and CD come in line, marked on the map): there C can move with both cranks held and the mechanism may switch its assembly mode. Keep the path of C away from them.</source>
        <translation>Радни простор ових режима досеже сингуларитете директне кинематике (криве на којима спојке BC и CD долазе на исту праву, означене на мапи): ту се C може померати и кад су обе полуге закочене, а механизам може да промени начин склапања. Држите путању тачке C даље од њих.</translation>
    </message>
    <message>
        <source>crank AB angle at A, from +x counter-clockwise (actuated)</source>
        <translation>угао полуге AB у A, од +x супротно смеру казаљке на сату (погонска координата)</translation>
    </message>
    <message>
        <source>crank ED angle at E, from +x counter-clockwise (actuated)</source>
        <translation>угао полуге ED у E, од +x супротно смеру казаљке на сату (погонска координата)</translation>
    </message>
    <message>
        <source>output point C, x</source>
        <translation>излазна тачка C, x</translation>
    </message>
    <message>
        <source>output point C, y</source>
        <translation>излазна тачка C, y</translation>
    </message>
    <message>
        <source>At theta1 = %1, theta4 = %2 the distal links cannot meet: |BD| = %3 is more than BC + CD = %4 (past the dead point where BC and CD are stretched in line, a direct singularity).</source>
        <translation>При theta1 = %1, theta4 = %2 спојке не могу да се споје: |BD| = %3 је веће од BC + CD = %4 (иза мртве тачке у којој су BC и CD опружене на истој правој, сингуларитета директне кинематике).</translation>
    </message>
    <message>
        <source>At theta1 = %1, theta4 = %2 the distal links cannot meet: |BD| = %3 is less than |BC − CD| = %4 (past the dead point where BC and CD fold in line, a direct singularity).</source>
        <translation>При theta1 = %1, theta4 = %2 спојке не могу да се споје: |BD| = %3 је мање од |BC − CD| = %4 (иза мртве тачке у којој се BC и CD пресавијају на истој правој, сингуларитета директне кинематике).</translation>
    </message>
    <message>
        <source>At theta1 = %1, theta4 = %2 the elbows B and D coincide and BC = CD: the position of C is undetermined.</source>
        <translation>При theta1 = %1, theta4 = %2 зглобови B и D се поклапају, а BC = CD: положај C није одређен.</translation>
    </message>
    <message>
        <source>At theta1 = %1, theta4 = %2 leg %3 would be in its other working mode (%4): crank %5 and link %6 pass through in line (an inverse singularity) on the way; switch %7 to go on.</source>
        <translation>При theta1 = %1, theta4 = %2 нога %3 би била у другом радном режиму (%4): полуга %5 и спојка %6 успут пролазе кроз положај на истој правој (сингуларитет инверзне кинематике); промените %7 да бисте наставили.</translation>
    </message>
    <message>
        <source>C cannot reach %1: it lies %2 from %3, more than %4 + %5 = %6.</source>
        <translation>C не може да стигне до тачке %1: она је на %2 од %3, више од %4 + %5 = %6.</translation>
    </message>
    <message>
        <source>C cannot reach %1: it lies %2 from %3, less than |%4 − %5| = %6.</source>
        <translation>C не може да стигне до тачке %1: она је на %2 од %3, мање од |%4 − %5| = %6.</translation>
    </message>
    <message>
        <source>C = %1 lies on %2 and %3 = %4: the crank angle %5 is undetermined.</source>
        <translation>C = %1 се поклапа са %2, а %3 = %4: угао полуге %5 није одређен.</translation>
    </message>
    <message>
        <source>C cannot reach %1: crank %2 would have to be at %3 = %4, outside its range %5.</source>
        <translation>C не може да стигне до тачке %1: полуга %2 би морала да буде на %3 = %4, ван свог опсега %5.</translation>
    </message>
    <message>
        <source>No failure.</source>
        <translation>Нема грешке.</translation>
    </message>
    <message>
        <source>%1 must be a finite number.</source>
        <translation>%1 мора бити коначан број.</translation>
    </message>
    <message>
        <source>%1 = %2 is outside the range of crank %3, %4: the crank turns fully, give its angle within it.</source>
        <translation>%1 = %2 је ван опсега полуге %3, %4: полуга се окреће пуним кругом, задајте угао унутар тог опсега.</translation>
    </message>
    <message>
        <source>%1 = %2 is outside the range of crank %3, %4.</source>
        <translation>%1 = %2 је ван опсега полуге %3, %4.</translation>
    </message>
    <message>
        <source>crank AB angle at A, from +x counter-clockwise</source>
        <translation>угао полуге AB у A, од +x супротно смеру казаљке на сату</translation>
    </message>
    <message>
        <source>crank ED angle at E, from +x counter-clockwise</source>
        <translation>угао полуге ED у E, од +x супротно смеру казаљке на сату</translation>
    </message>
    <message>
        <source>J_x rows (C − B)ᵀ, (C − D)ᵀ</source>
        <translation>врсте J_x: (C − B)ᵀ, (C − D)ᵀ</translation>
    </message>
    <message>
        <source>determinant of J (0: direct, ∞: inverse singularity)</source>
        <translation>детерминанта J (0: сингуларитет директне, ∞: инверзне кинематике)</translation>
    </message>
    <message>
        <source>0 at an inverse singularity (a leg stretched or folded)</source>
        <translation>0 у сингуларитету инверзне кинематике (нога опружена или пресавијена)</translation>
    </message>
    <message>
        <source>0 at a direct singularity (the distal links in line)</source>
        <translation>0 у сингуларитету директне кинематике (спојке на истој правој)</translation>
    </message>
    <message>
        <source>condition number of J</source>
        <translation>број условљености J</translation>
    </message>
    <message>
        <source>angle ABC between crank AB and link BC (0°, 180°: inverse singularity)</source>
        <translation>угао ABC између полуге AB и спојке BC (0°, 180°: сингуларитет инверзне кинематике)</translation>
    </message>
    <message>
        <source>angle EDC between crank ED and link DC (0°, 180°: inverse singularity)</source>
        <translation>угао EDC између полуге ED и спојке DC (0°, 180°: сингуларитет инверзне кинематике)</translation>
    </message>
    <message>
        <source>angle BCD between the distal links (0°, 180°: direct singularity)</source>
        <translation>угао BCD између спојки (0°, 180°: сингуларитет директне кинематике)</translation>
    </message>
    <message>
        <source>transmission angle between the distal links, min(ψ, 180° − ψ)</source>
        <translation>угао преноса између спојки, min(ψ, 180° − ψ)</translation>
    </message>
    <message>
        <source>distance from the inverse singularities, min |sin φ_i| (0 … 1)</source>
        <translation>удаљеност од сингуларитета инверзне кинематике, min |sin φ_i| (0 … 1)</translation>
    </message>
    <message>
        <source>distance from the direct singularities, |sin ψ| (0 … 1)</source>
        <translation>удаљеност од сингуларитета директне кинематике, |sin ψ| (0 … 1)</translation>
    </message>
    <message>
        <source>distance from the nearest singularity (0 … 1)</source>
        <translation>удаљеност од најближег сингуларитета (0 … 1)</translation>
    </message>
    <message>
        <source>other assembly mode (C right of B→D, same crank angles)</source>
        <translation>други начин склапања (C десно од B→D, исти углови полуга)</translation>
    </message>
    <message>
        <source>other assembly mode (C left of B→D, same crank angles)</source>
        <translation>други начин склапања (C лево од B→D, исти углови полуга)</translation>
    </message>
    <message>
        <source>leg 1: other working mode (B left of A→C, same C)</source>
        <translation>нога 1: други радни режим (B лево од A→C, иста тачка C)</translation>
    </message>
    <message>
        <source>leg 1: other working mode (B right of A→C, same C)</source>
        <translation>нога 1: други радни режим (B десно од A→C, иста тачка C)</translation>
    </message>
    <message>
        <source>leg 2: other working mode (D left of E→C, same C)</source>
        <translation>нога 2: други радни режим (D лево од E→C, иста тачка C)</translation>
    </message>
    <message>
        <source>leg 2: other working mode (D right of E→C, same C)</source>
        <translation>нога 2: други радни режим (D десно од E→C, иста тачка C)</translation>
    </message>
    <message>
        <source>ground</source>
        <translation>постоље</translation>
    </message>
    <message>
        <source>crank AB</source>
        <translation>полуга AB</translation>
    </message>
    <message>
        <source>link BC</source>
        <translation>спојка BC</translation>
    </message>
    <message>
        <source>link CD</source>
        <translation>спојка CD</translation>
    </message>
    <message>
        <source>crank DE</source>
        <translation>полуга DE</translation>
    </message>
    <message>
        <source>planar five-bar: ground AE, cranks AB and DE (driven at A and E), distal links BC and CD</source>
        <translation>равански зглобни петоугао: постоље AE, полуге AB и DE (погон у A и E), спојке BC и CD</translation>
    </message>
    <message>
        <source>drag to move C (inverse kinematics)</source>
        <translation>превуците да бисте померили C (инверзна кинематика)</translation>
    </message>
    <message>
        <source>drag to turn crank AB (sets θ₁, direct kinematics)</source>
        <translation>превуците да бисте заокренули полугу AB (задаје θ₁, директна кинематика)</translation>
    </message>
    <message>
        <source>drag to turn crank DE (sets θ₄, direct kinematics)</source>
        <translation>превуците да бисте заокренули полугу DE (задаје θ₄, директна кинематика)</translation>
    </message>
    <message>
        <source>No handle with that index.</source>
        <translation>Нема ручице са тим индексом.</translation>
    </message>
    <message>
        <source>crank and distal link in line</source>
        <translation>полуга и спојка на истој правој</translation>
    </message>
    <message>
        <source>distal links in line</source>
        <translation>спојке на истој правој</translation>
    </message>
    <message>
        <source>leg 1 stretched (AB, BC in line)</source>
        <translation>нога 1 опружена (AB, BC на истој правој)</translation>
    </message>
    <message>
        <source>leg 1 folded (AB, BC in line)</source>
        <translation>нога 1 пресавијена (AB, BC на истој правој)</translation>
    </message>
    <message>
        <source>leg 2 stretched (DE, CD in line)</source>
        <translation>нога 2 опружена (DE, CD на истој правој)</translation>
    </message>
    <message>
        <source>leg 2 folded (DE, CD in line)</source>
        <translation>нога 2 пресавијена (DE, CD на истој правој)</translation>
    </message>
    <message>
        <source>rad/s²</source>
        <translation>rad/s²</translation>
    </message>
    <message>
        <source>crossed</source>
        <translation>укрштена</translation>
    </message>
    <message>
        <source>open</source>
        <translation>отворена</translation>
    </message>
    <message>
        <source>crank-rocker</source>
        <translation>полуга–клацкалица</translation>
    </message>
    <message>
        <source>rocker-crank</source>
        <translation>клацкалица–полуга</translation>
    </message>
    <message>
        <source>double-crank</source>
        <translation>двострука полуга</translation>
    </message>
    <message>
        <source>double-rocker</source>
        <translation>двострука клацкалица</translation>
    </message>
    <message>
        <source>triple-rocker</source>
        <translation>трострука клацкалица</translation>
    </message>
    <message>
        <source>change-point</source>
        <translation>прелазни</translation>
    </message>
    <message>
        <source>crank (input link) length</source>
        <translation>дужина полуге (улазног члана)</translation>
    </message>
    <message>
        <source>coupler length</source>
        <translation>дужина спојке</translation>
    </message>
    <message>
        <source>rocker (output link) length</source>
        <translation>дужина клацкалице (излазног члана)</translation>
    </message>
    <message>
        <source>ground (frame) length</source>
        <translation>дужина постоља (непокретног члана)</translation>
    </message>
    <message>
        <source>crank angular velocity, constant (positive: α grows, counter-clockwise)</source>
        <translation>угаона брзина полуге, константна (позитивна: α расте, супротно од казаљке на сату)</translation>
    </message>
    <message>
        <source>coupler point M on BC: BM/BC (0 at B, 1 at C)</source>
        <translation>тачка M спојке на BC: BM/BC (0 у B, 1 у C)</translation>
    </message>
    <message>
        <source>assembly branch: +1 open (C left of B→D), −1 crossed</source>
        <translation>грана склапања: +1 отворена (C лево од B→D), −1 укрштена</translation>
    </message>
    <message>
        <source>branch = %1 is invalid: it must be +1 (open) or -1 (crossed).</source>
        <translation>branch = %1 није допуштена вредност: мора бити +1 (отворена) или -1 (укрштена).</translation>
    </message>
    <message>
        <source>The four-bar linkage has no parameter named &apos;%1&apos;.</source>
        <translation>Зглобни четвороугао нема параметар „%1“.</translation>
    </message>
    <message>
        <source>%1 = %2 is not shorter than %3 = %4: the links cannot close the loop ABCD for any crank angle α (each link must be shorter than the other three together).</source>
        <translation>%1 = %2 није краће од %3 = %4: чланови не могу да затворе контуру ABCD ни за један угао полуге α (сваки члан мора бити краћи од збира остала три).</translation>
    </message>
    <message>
        <source>at α = %1 the diagonal |BD| reaches BC + CD = %2: the coupler and the rocker are stretched in line (a dead point), and beyond it they cannot reach each other</source>
        <translation>при α = %1 дијагонала |BD| достиже BC + CD = %2: спојка и клацкалица су опружене у линију (мртва тачка), а даље не могу да се споје</translation>
    </message>
    <message>
        <source>at α = %1 the diagonal |BD| falls to |BC − CD| = %2: the coupler and the rocker are folded in line (a dead point), and beyond it they cannot close the loop</source>
        <translation>при α = %1 дијагонала |BD| пада на |BC − CD| = %2: спојка и клацкалица су склопљене у линију (мртва тачка), а даље не могу да затворе контуру</translation>
    </message>
    <message>
        <source>s + l = p + q (a change-point linkage): the links fold flat in line somewhere in the motion, where the open and crossed branches meet and a real linkage may switch branch.</source>
        <translation>s + l = p + q (прелазни механизам): у неком положају чланови се склапају у линију; ту се сусрећу отворена и укрштена грана и стварни механизам може да пређе на другу грану.</translation>
    </message>
    <message>
        <source>The crank cannot turn fully: α is limited to [%1, %2], at whose ends the coupler and the rocker are in line (dead points where the crank cannot drive the rocker).</source>
        <translation>Полуга не може да се окреће пун круг: α је ограничен на [%1, %2], а на крајевима тог интервала спојка и клацкалица су у линији (мртве тачке у којима полуга не може да покреће клацкалицу).</translation>
    </message>
    <message>
        <source>The transmission angle falls to %1 at α = %2 (below %3°): the crank drives the rocker poorly there.</source>
        <translation>Угао преноса пада на %1 при α = %2 (испод %3°): ту полуга лоше покреће клацкалицу.</translation>
    </message>
    <message>
        <source>crank angle at A, from AD counter-clockwise (actuated)</source>
        <translation>угао полуге у A, од AD супротно од казаљке на сату (погоњен)</translation>
    </message>
    <message>
        <source>rocker angle at D, from DA clockwise (output)</source>
        <translation>угао клацкалице у D, од DA у смеру казаљке на сату (излаз)</translation>
    </message>
    <message>
        <source>alpha must be a finite number.</source>
        <translation>Вредност alpha мора бити коначан број.</translation>
    </message>
    <message>
        <source>alpha = %1 is outside [0°, 360°]: the crank turns fully, give its angle within one turn.</source>
        <translation>alpha = %1 је ван [0°, 360°]: полуга се окреће пун круг, задајте њен угао унутар једног обртаја.</translation>
    </message>
    <message>
        <source>alpha = %1 is outside the range of the crank of this %2 linkage, [%3, %4]: %5.</source>
        <translation>alpha = %1 је ван опсега полуге овог механизма (тип по Грасхофу: %2), [%3, %4]: %5.</translation>
    </message>
    <message>
        <source>At alpha = %1 the crank joint B lies on D: the rocker&apos;s angle is undetermined.</source>
        <translation>При alpha = %1 зглоб полуге B пада у D: угао клацкалице није одређен.</translation>
    </message>
    <message>
        <source>The loop ABCD does not close at alpha = %1.</source>
        <translation>Контура ABCD се не затвара при alpha = %1.</translation>
    </message>
    <message>
        <source>delta must be a finite number.</source>
        <translation>Вредност delta мора бити коначан број.</translation>
    </message>
    <message>
        <source>delta = %1 is outside the range the rocker reaches in the crossed branch, [%2, %3]: at its ends the crank and the coupler are in line, or the crank is at its own limit.</source>
        <translation>delta = %1 је ван опсега који клацкалица достиже у укрштеној грани, [%2, %3]: на његовим крајевима полуга и спојка су у линији или је полуга на сопственој граници.</translation>
    </message>
    <message>
        <source>delta = %1 is outside the range the rocker reaches in the open branch, [%2, %3]: at its ends the crank and the coupler are in line, or the crank is at its own limit.</source>
        <translation>delta = %1 је ван опсега који клацкалица достиже у отвореној грани, [%2, %3]: на његовим крајевима полуга и спојка су у линији или је полуга на сопственој граници.</translation>
    </message>
    <message>
        <source>At delta = %1 the rocker joint C lies on A: the crank angle is undetermined.</source>
        <translation>При delta = %1 зглоб клацкалице C пада у A: угао полуге није одређен.</translation>
    </message>
    <message>
        <source>The crank cannot reach the coupler at delta = %1: |AC| = %2 is not between |AB − BC| and AB + BC.</source>
        <translation>При delta = %1 полуга не може да досегне спојку: |AC| = %2 није између |AB − BC| и AB + BC.</translation>
    </message>
    <message>
        <source>The rocker reaches delta = %1 only in the other assembly branch; this design is crossed.</source>
        <translation>Клацкалица достиже delta = %1 само у другој грани склапања; ова конструкција је склопљена у укрштеној грани.</translation>
    </message>
    <message>
        <source>The rocker reaches delta = %1 only in the other assembly branch; this design is open.</source>
        <translation>Клацкалица достиже delta = %1 само у другој грани склапања; ова конструкција је склопљена у отвореној грани.</translation>
    </message>
    <message>
        <source>crank angle at A, from AD counter-clockwise</source>
        <translation>угао полуге у A, од AD супротно од казаљке на сату</translation>
    </message>
    <message>
        <source>rocker angle at D, from DA clockwise</source>
        <translation>угао клацкалице у D, од DA у смеру казаљке на сату</translation>
    </message>
    <message>
        <source>transmission angle at C, from CB to CD counter-clockwise (&lt; 0: crossed)</source>
        <translation>угао преноса у C, од CB ка CD супротно од казаљке на сату (&lt; 0: укрштена грана)</translation>
    </message>
    <message>
        <source>angle at D from DA to DB (4)</source>
        <translation>угао у D од DA ка DB (4)</translation>
    </message>
    <message>
        <source>angle at B from BA to BC, 360° − (α + γ + δ)</source>
        <translation>угао у B од BA ка BC, 360° − (α + γ + δ)</translation>
    </message>
    <message>
        <source>J_q = ∂F/∂α = 2·AB·BC·sin β (0: inverse singularity)</source>
        <translation>J_q = ∂F/∂α = 2·AB·BC·sin β (0: сингуларитет инверзне кинематике)</translation>
    </message>
    <message>
        <source>J_x = −∂F/∂δ = −2·BC·CD·sin γ (0: direct singularity)</source>
        <translation>J_x = −∂F/∂δ = −2·BC·CD·sin γ (0: сингуларитет директне кинематике)</translation>
    </message>
    <message>
        <source>α̇ = J·δ̇, J = J_q⁻¹·J_x = dα/dδ</source>
        <translation>α̇ = J·δ̇, J = J_q⁻¹·J_x = dα/dδ</translation>
    </message>
    <message>
        <source>transfer function dδ/dα = ω₃/ω₁ = −(9)</source>
        <translation>преносна функција dδ/dα = ω₃/ω₁ = −(9)</translation>
    </message>
    <message>
        <source>crank angular velocity (constant)</source>
        <translation>угаона брзина полуге (константна)</translation>
    </message>
    <message>
        <source>coupler angular velocity, counter-clockwise</source>
        <translation>угаона брзина спојке, супротно од казаљке на сату</translation>
    </message>
    <message>
        <source>dδ/dt, exact (the document&apos;s (8) with the opposite sign)</source>
        <translation>dδ/dt, тачна вредност (формула (8) из рада са супротним знаком)</translation>
    </message>
    <message>
        <source>coupler angular acceleration, counter-clockwise</source>
        <translation>угаоно убрзање спојке, супротно од казаљке на сату</translation>
    </message>
    <message>
        <source>d²δ/dt² at constant ω₁, exact (not the document&apos;s (14))</source>
        <translation>d²δ/dt² при константној ω₁, тачна вредност (не формула (14) из рада)</translation>
    </message>
    <message>
        <source>acute transmission angle min(|γ|, 180° − |γ|) (below 40°: poor)</source>
        <translation>оштар угао преноса min(|γ|, 180° − |γ|) (испод 40°: лош пренос)</translation>
    </message>
    <message>
        <source>distance from the nearest singularity, min(|sin β|, |sin γ|)</source>
        <translation>удаљеност од најближег сингуларитета, min(|sin β|, |sin γ|)</translation>
    </message>
    <message>
        <source>diagonal |BD|</source>
        <translation>дијагонала |BD|</translation>
    </message>
    <message>
        <source>coupler point M, x</source>
        <translation>тачка спојке M, x</translation>
    </message>
    <message>
        <source>coupler point M, y</source>
        <translation>тачка спојке M, y</translation>
    </message>
    <message>
        <source>instantaneous centre P of the coupler, x (none: AB ∥ DC)</source>
        <translation>тренутни пол брзина P спојке, x (нема: AB ∥ DC)</translation>
    </message>
    <message>
        <source>instantaneous centre P of the coupler, y (none: AB ∥ DC)</source>
        <translation>тренутни пол брзина P спојке, y (нема: AB ∥ DC)</translation>
    </message>
    <message>
        <source>assembly branch: open (C left of B→D) or crossed</source>
        <translation>грана склапања: отворена (C лево од B→D) или укрштена</translation>
    </message>
    <message>
        <source>Grashof class from s + l against p + q</source>
        <translation>тип по Грасхофу: s + l у поређењу са p + q</translation>
    </message>
    <message>
        <source>crossed branch (same crank angle)</source>
        <translation>укрштена грана (исти угао полуге)</translation>
    </message>
    <message>
        <source>open branch (same crank angle)</source>
        <translation>отворена грана (исти угао полуге)</translation>
    </message>
    <message>
        <source>ground AD</source>
        <translation>постоље AD</translation>
    </message>
    <message>
        <source>coupler BC</source>
        <translation>спојка BC</translation>
    </message>
    <message>
        <source>rocker CD</source>
        <translation>клацкалица CD</translation>
    </message>
    <message>
        <source>planar four-bar: ground AD, crank AB (driven at A), coupler BC, rocker CD</source>
        <translation>равански зглобни четвороугао: постоље AD, полуга AB (погон у A), спојка BC, клацкалица CD</translation>
    </message>
    <message>
        <source>BC (P at infinity: AB ∥ DC, the coupler translates)</source>
        <translation>BC (P у бесконачности: AB ∥ DC, спојка се креће транслаторно)</translation>
    </message>
    <message>
        <source>drag to turn the crank (sets α, direct kinematics)</source>
        <translation>превуците да окренете полугу (задаје α, директна кинематика)</translation>
    </message>
    <message>
        <source>drag to swing the rocker (sets δ, inverse kinematics)</source>
        <translation>превуците да померите клацкалицу (задаје δ, инверзна кинематика)</translation>
    </message>
    <message>
        <source>coupler curve of M (crossed branch)</source>
        <translation>спојна крива тачке M (укрштена грана)</translation>
    </message>
    <message>
        <source>coupler curve of M (open branch)</source>
        <translation>спојна крива тачке M (отворена грана)</translation>
    </message>
    <message>
        <source>No joint variable with that index.</source>
        <translation>Не постоји зглобна координата са тим бројем.</translation>
    </message>
    <message>
        <source>not a number</source>
        <translation>није број</translation>
    </message>
    <message>
        <source>%1 (%2) = %3 is invalid: it must be greater than %4.</source>
        <translation>%1 (%2) = %3 није дозвољена вредност: мора бити веће од %4.</translation>
    </message>
    <message>
        <source>%1 (%2) = %3 is invalid: it must be at least %4.</source>
        <translation>%1 (%2) = %3 није дозвољена вредност: мора бити најмање %4.</translation>
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
        <translation>%1 (%2) = %3 није дозвољена вредност: мора бити у опсегу %4.</translation>
    </message>
    <message>
        <source>no kinematic chain is described for this mechanism</source>
        <translation>за овај механизам није описан кинематички ланац</translation>
    </message>
    <message>
        <source>pair &apos;%1&apos; does not join two different links of the chain</source>
        <translation>пар „%1“ не спаја два различита члана ланца</translation>
    </message>
    <message>
        <source>pair &apos;%1&apos; has a point or an axis that is not finite</source>
        <translation>пар „%1“ има тачку или осу која није коначна</translation>
    </message>
    <message>
        <source>pair &apos;%1&apos; has no axis</source>
        <translation>пар „%1“ нема осу</translation>
    </message>
    <message>
        <source>the chain is marked planar (the plane z = 0) but pair &apos;%1&apos; is not</source>
        <translation>ланац је означен као равански (раван z = 0), али пар „%1“ није</translation>
    </message>
    <message numerus="yes">
        <source>%n moving link(s)</source>
        <translation>
            <numerusform>%n покретни члан</numerusform>
            <numerusform>%n покретна члана</numerusform>
            <numerusform>%n покретних чланова</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n pair(s)</source>
        <translation>
            <numerusform>%n кинематички пар</numerusform>
            <numerusform>%n кинематичка пара</numerusform>
            <numerusform>%n кинематичких парова</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n loop(s)</source>
        <translation>
            <numerusform>%n затворена контура</numerusform>
            <numerusform>%n затворене контуре</numerusform>
            <numerusform>%n затворених контура</numerusform>
        </translation>
    </message>
    <message>
        <source>Planar chain of %1, %2 and %3: the rank of its constraint Jacobian gives mobility %4</source>
        <translation>Равански ланац (%1, %2 и %3): ранг његове Јакобијеве матрице веза даје покретљивост %4</translation>
    </message>
    <message>
        <source>Spatial chain of %1, %2 and %3: the rank of its constraint Jacobian gives mobility %4</source>
        <translation>Просторни ланац (%1, %2 и %3): ранг његове Јакобијеве матрице веза даје покретљивост %4</translation>
    </message>
    <message numerus="yes">
        <source>Chebyshev&apos;s W = %1 is wrong: %n planar loop equation(s) is/are redundant (an overconstrained planar chain)</source>
        <translation>
            <numerusform>Чебишевљева формула даје W = %1, што је погрешно: %n једначина равних контура је сувишна (равански ланац са сувишним везама)</numerusform>
            <numerusform>Чебишевљева формула даје W = %1, што је погрешно: %n једначине равних контура су сувишне (равански ланац са сувишним везама)</numerusform>
            <numerusform>Чебишевљева формула даје W = %1, што је погрешно: %n једначина равних контура је сувишно (равански ланац са сувишним везама)</numerusform>
        </translation>
    </message>
    <message>
        <source>Chebyshev&apos;s W = %1 is right</source>
        <translation>Чебишевљева формула даје W = %1, што је тачно</translation>
    </message>
    <message>
        <source>Somov–Malyshev&apos;s W = %1 is right</source>
        <translation>формула Сомова–Малишева даје W = %1, што је тачно</translation>
    </message>
    <message>
        <source>(parallel axes: a planar loop imposes only 3)</source>
        <translation>(паралелне осе: раванска контура намеће само 3)</translation>
    </message>
    <message>
        <source>(an overconstrained, &quot;paradoxical&quot; chain: it moves)</source>
        <translation>(„парадоксалан“ ланац са сувишним везама: покретан је)</translation>
    </message>
    <message>
        <source>(an overconstrained chain)</source>
        <translation>(ланац са сувишним везама)</translation>
    </message>
    <message numerus="yes">
        <source>Somov–Malyshev&apos;s W = %1 is wrong: it counts 6 equations per loop and %n is/are redundant %2</source>
        <translation>
            <numerusform>формула Сомова–Малишева даје W = %1, што је погрешно: она рачуна 6 једначина по контури, а %n од њих је сувишна %2</numerusform>
            <numerusform>формула Сомова–Малишева даје W = %1, што је погрешно: она рачуна 6 једначина по контури, а %n од њих су сувишне %2</numerusform>
            <numerusform>формула Сомова–Малишева даје W = %1, што је погрешно: она рачуна 6 једначина по контури, а %n од њих је сувишно %2</numerusform>
        </translation>
    </message>
    <message>
        <source>at this pose the rank drops: the instantaneous mobility is %1, a singular pose</source>
        <translation>у овом положају ранг опада: тренутна покретљивост је %1, сингуларан положај</translation>
    </message>
    <message>
        <source>no pair is actuated</source>
        <translation>ниједан пар није погоњен</translation>
    </message>
    <message numerus="yes">
        <source>%n freedom(s)</source>
        <translation>
            <numerusform>%n степен слободе</numerusform>
            <numerusform>%n степена слободе</numerusform>
            <numerusform>%n степени слободе</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n actuated freedom(s) leave(s) %1 uncontrolled (under-actuated)</source>
        <translation>
            <numerusform>%n погоњени степен слободе: без управљања остаје %1 (недовољно погона)</numerusform>
            <numerusform>%n погоњена степена слободе: без управљања остаје %1 (недовољно погона)</numerusform>
            <numerusform>%n погоњених степени слободе: без управљања остаје %1 (недовољно погона)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n actuated freedom(s) for mobility %1: redundantly actuated</source>
        <translation>
            <numerusform>%n погоњени степен слободе за покретљивост %1: сувишан број погона</numerusform>
            <numerusform>%n погоњена степена слободе за покретљивост %1: сувишан број погона</numerusform>
            <numerusform>%n погоњених степени слободе за покретљивост %1: сувишан број погона</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n actuated freedom(s): fully actuated</source>
        <translation>
            <numerusform>%n погоњени степен слободе: механизам је потпуно погоњен</numerusform>
            <numerusform>%n погоњена степена слободе: механизам је потпуно погоњен</numerusform>
            <numerusform>%n погоњених степени слободе: механизам је потпуно погоњен</numerusform>
        </translation>
    </message>
    <message>
        <source>with the actuators locked it can still move instantaneously here (a direct singularity)</source>
        <translation>са закоченим погонима ланац се овде још може тренутно померити (сингуларитет директне кинематике)</translation>
    </message>
    <message numerus="yes">
        <source>%n idle freedom(s) is/are included</source>
        <translation>
            <numerusform>укључујући локалне степене слободе: %n</numerusform>
            <numerusform>укључујући локалне степене слободе: %n</numerusform>
            <numerusform>укључујући локалне степене слободе: %n</numerusform>
        </translation>
    </message>
    <message>
        <source>link %1</source>
        <translation>члан %1</translation>
    </message>
    <message>
        <source>ground OB</source>
        <translation>постоље OB</translation>
    </message>
    <message>
        <source>crank OC</source>
        <translation>полуга OC</translation>
    </message>
    <message>
        <source>coupler CA</source>
        <translation>спојка CA</translation>
    </message>
    <message>
        <source>spatial parallelogram: four parallel revolute axes taken as a spatial chain</source>
        <translation>просторни паралелограм: четири паралелне осе обртних парова, посматране као просторни ланац</translation>
    </message>
    <message>
        <source>Bennett linkage: four revolute axes, opposite links equal, a/sin α = b/sin β</source>
        <translation>Бенетов механизам: четири осе обртних парова, наспрамни чланови једнаки, a/sin α = b/sin β</translation>
    </message>
    <message>
        <source>spatial 4R loop with random axes (not a Bennett linkage)</source>
        <translation>просторна контура 4R са случајним осама (није Бенетов механизам)</translation>
    </message>
    <message>
        <source>ground AE</source>
        <translation>постоље AE</translation>
    </message>
    <message>
        <source>link DC</source>
        <translation>спојка DC</translation>
    </message>
    <message>
        <source>crank ED</source>
        <translation>полуга ED</translation>
    </message>
    <message>
        <source>planar five-bar: ground, two driven cranks, two distal links</source>
        <translation>равански петочлани механизам: постоље, две погоњене полуге, две спојке</translation>
    </message>
    <message>
        <source>Cannot analyse the mobility: %1.</source>
        <translation>Покретљивост не може да се одреди: %1.</translation>
    </message>
    <message>
        <source>crank BA</source>
        <translation>полуга BA</translation>
    </message>
    <message>
        <source>%1 (back)</source>
        <translation>%1 (позади)</translation>
    </message>
    <message>
        <source>%1 (front)</source>
        <translation>%1 (напред)</translation>
    </message>
    <message>
        <source>base</source>
        <translation>основа</translation>
    </message>
    <message>
        <source>clevis</source>
        <translation>виљушка</translation>
    </message>
    <message>
        <source>stepper motor</source>
        <translation>корачни мотор</translation>
    </message>
    <message>
        <source>lead screw</source>
        <translation>завојно вретено</translation>
    </message>
    <message>
        <source>rod end</source>
        <translation>зглобни завршетак вретена</translation>
    </message>
    <message>
        <source>guide %1</source>
        <translation>вођица %1</translation>
    </message>
    <message>
        <source>end stop</source>
        <translation>граничник</translation>
    </message>
    <message>
        <source>carriage %1</source>
        <translation>колица %1</translation>
    </message>
    <message>
        <source>platform</source>
        <translation>платформа</translation>
    </message>
    <message>
        <source>guide 1 reference point, x</source>
        <translation>референтна тачка вођице 1, x</translation>
    </message>
    <message>
        <source>guide 1 reference point, y</source>
        <translation>референтна тачка вођице 1, y</translation>
    </message>
    <message>
        <source>guide 2 reference point, x</source>
        <translation>референтна тачка вођице 2, x</translation>
    </message>
    <message>
        <source>guide 2 reference point, y</source>
        <translation>референтна тачка вођице 2, y</translation>
    </message>
    <message>
        <source>direction of guide 1</source>
        <translation>оријентација вођице 1</translation>
    </message>
    <message>
        <source>direction of guide 2</source>
        <translation>оријентација вођице 2</translation>
    </message>
    <message>
        <source>turn of guide 1 from the vertical (α₁ = 270° + γ₁)</source>
        <translation>заокрет вођице 1 од вертикале (α₁ = 270° + γ₁)</translation>
    </message>
    <message>
        <source>turn of guide 2 from the vertical (α₂ = 270° + γ₂)</source>
        <translation>заокрет вођице 2 од вертикале (α₂ = 270° + γ₂)</translation>
    </message>
    <message>
        <source>length of link S₁</source>
        <translation>дужина спојке S₁</translation>
    </message>
    <message>
        <source>length of link S₂</source>
        <translation>дужина спојке S₂</translation>
    </message>
    <message>
        <source>start of the stroke</source>
        <translation>почетак хода</translation>
    </message>
    <message>
        <source>end of the stroke</source>
        <translation>крај хода</translation>
    </message>
    <message>
        <source>working mode of leg 1: sign in p₁ = B₁ ± √…</source>
        <translation>радни режим ноге 1: знак у p₁ = B₁ ± √…</translation>
    </message>
    <message>
        <source>working mode of leg 2: sign in p₂ = B₂ ± √…</source>
        <translation>радни режим ноге 2: знак у p₂ = B₂ ± √…</translation>
    </message>
    <message>
        <source>assembly mode: +1 platform left of Z₁→Z₂</source>
        <translation>начин склапања: +1 платформа лево од Z₁→Z₂</translation>
    </message>
    <message>
        <source>links kept on the inner side of the guides (1: on)</source>
        <translation>спојке само са унутрашње стране вођица (1: укључено)</translation>
    </message>
    <message>
        <source>drawn width of a guide</source>
        <translation>ширина вођице на цртежу</translation>
    </message>
    <message>
        <source>MOMA has no parameter named &apos;%1&apos;.</source>
        <translation>MOMA нема параметар „%1“.</translation>
    </message>
    <message>
        <source>%1 and %2 both turn guide %3: give one of them.</source>
        <translation>%1 и %2 оба закрећу вођицу %3: задајте само један од њих.</translation>
    </message>
    <message>
        <source>%1 = %2 is invalid: it must be -1 or +1.</source>
        <translation>%1 = %2 није дозвољена вредност: мора бити -1 или +1.</translation>
    </message>
    <message>
        <source>one_side = %1 is invalid: it must be 0 (off) or 1 (on).</source>
        <translation>one_side = %1 није дозвољена вредност: мора бити 0 (искључено) или 1 (укључено).</translation>
    </message>
    <message>
        <source>p_min = %1 mm must be less than p_max = %2 mm.</source>
        <translation>p_min = %1 mm мора бити мање од p_max = %2 mm.</translation>
    </message>
    <message>
        <source>The guides lie on one line and their strokes overlap: the slider joints Z₁ and Z₂ could coincide. Move R₂ or turn a guide.</source>
        <translation>Вођице леже на истој правој и ходови им се преклапају: зглобови клизача Z₁ и Z₂ могу да се поклопе. Померите R₂ или заокрените вођицу.</translation>
    </message>
    <message>
        <source>This configuration has no workspace: with l₁ = %1 mm, l₂ = %2 mm and strokes [%3, %4] mm the links cannot meet in the chosen working and assembly modes.</source>
        <translation>Ова конфигурација нема радни простор: са l₁ = %1 mm, l₂ = %2 mm и ходом [%3; %4] mm спојке не могу да се споје у изабраним радним режимима и начину склапања.</translation>
    </message>
    <message>
        <source>The guides cross inside their strokes: the sliders can collide there.</source>
        <translation>Вођице се секу унутар хода: ту клизачи могу да се сударе.</translation>
    </message>
    <message>
        <source>slider 1 position (actuated)</source>
        <translation>положај клизача 1 (погонска координата)</translation>
    </message>
    <message>
        <source>slider 2 position (actuated)</source>
        <translation>положај клизача 2 (погонска координата)</translation>
    </message>
    <message>
        <source>platform x</source>
        <translation>платформа, x</translation>
    </message>
    <message>
        <source>platform y</source>
        <translation>платформа, y</translation>
    </message>
    <message>
        <source>link S%1 would lie on the outer side of guide %2 (the one-side constraint is on)</source>
        <translation>спојка S%1 би се нашла са спољашње стране вођице %2 (укључено је ограничење на једну страну)</translation>
    </message>
    <message>
        <source>The slider joints Z₁ and Z₂ coincide at p₁ = %1 mm, p₂ = %2 mm: the platform position is undetermined.</source>
        <translation>Зглобови клизача Z₁ и Z₂ се поклапају при p₁ = %1 mm, p₂ = %2 mm: положај платформе није одређен.</translation>
    </message>
    <message>
        <source>The links cannot meet at p₁ = %1 mm, p₂ = %2 mm: |Z₁Z₂| = %3 mm is more than l₁ + l₂ = %4 mm.</source>
        <translation>Спојке не могу да се споје при p₁ = %1 mm, p₂ = %2 mm: |Z₁Z₂| = %3 mm је веће од l₁ + l₂ = %4 mm.</translation>
    </message>
    <message>
        <source>The links cannot meet at p₁ = %1 mm, p₂ = %2 mm: |Z₁Z₂| = %3 mm is less than |l₁ − l₂| = %4 mm.</source>
        <translation>Спојке не могу да се споје при p₁ = %1 mm, p₂ = %2 mm: |Z₁Z₂| = %3 mm је мање од |l₁ − l₂| = %4 mm.</translation>
    </message>
    <message>
        <source>At p₁ = %1 mm, p₂ = %2 mm leg %3 would be past perpendicular to its guide, in its other working mode (an inverse singularity lies between); switch the mode to go on.</source>
        <translation>При p₁ = %1 mm, p₂ = %2 mm нога %3 би прешла преко положаја управног на своју вођицу, у други радни режим (између је сингуларитет инверзне кинематике); промените режим да бисте наставили.</translation>
    </message>
    <message>
        <source>At p₁ = %1 mm, p₂ = %2 mm %3.</source>
        <translation>При p₁ = %1 mm, p₂ = %2 mm %3.</translation>
    </message>
    <message>
        <source>The platform cannot reach %1: it lies more than l%2 = %3 mm from guide %4.</source>
        <translation>Платформа не може да стигне до тачке %1: тачка је од вођице %4 удаљена више од l%2 = %3 mm.</translation>
    </message>
    <message>
        <source>The platform cannot reach %1: slider %2 would have to be at p%3 = %4 mm, outside its stroke [%5, %6] mm.</source>
        <translation>Платформа не може да стигне до тачке %1: клизач %2 би морао да буде на p%3 = %4 mm, ван свог хода [%5; %6] mm.</translation>
    </message>
    <message>
        <source>The platform cannot reach %1 in this assembly mode: it would cross the line Z₁Z₂, where the links are collinear (a direct singularity); switch the assembly mode to go on.</source>
        <translation>Платформа не може да стигне до тачке %1 у овом начину склапања: прешла би праву Z₁Z₂, на којој су спојке колинеарне (сингуларитет директне кинематике); промените начин склапања да бисте наставили.</translation>
    </message>
    <message>
        <source>The platform cannot reach %1: %2.</source>
        <translation>Платформа не може да стигне до тачке %1: %2.</translation>
    </message>
    <message>
        <source>%1 = %2 mm is outside the stroke [%3, %4] mm.</source>
        <translation>%1 = %2 mm је ван хода [%3; %4] mm.</translation>
    </message>
    <message>
        <source>slider 1 position</source>
        <translation>положај клизача 1</translation>
    </message>
    <message>
        <source>slider 2 position</source>
        <translation>положај клизача 2</translation>
    </message>
    <message>
        <source>J_x rows 2(P − Z_i) (20)</source>
        <translation>врсте J_x: 2(P − Z_i) (20)</translation>
    </message>
    <message>
        <source>ṗ = J·Ṗ, J = −J_p⁻¹·J_x ((21) up to its sign)</source>
        <translation>ṗ = J·Ṗ, J = −J_p⁻¹·J_x ((21) до на знак)</translation>
    </message>
    <message>
        <source>0 at an inverse singularity</source>
        <translation>0 у сингуларитету инверзне кинематике</translation>
    </message>
    <message>
        <source>0 at a direct singularity</source>
        <translation>0 у сингуларитету директне кинематике</translation>
    </message>
    <message>
        <source>angle between link S₁ and guide 1 (90°: inverse singularity)</source>
        <translation>угао између спојке S₁ и вођице 1 (90°: сингуларитет инверзне кинематике)</translation>
    </message>
    <message>
        <source>angle between link S₂ and guide 2 (90°: inverse singularity)</source>
        <translation>угао између спојке S₂ и вођице 2 (90°: сингуларитет инверзне кинематике)</translation>
    </message>
    <message>
        <source>angle between the links (0°, 180°: direct singularity)</source>
        <translation>угао између спојки (0°, 180°: сингуларитет директне кинематике)</translation>
    </message>
    <message>
        <source>other assembly mode (same slider positions)</source>
        <translation>други начин склапања (исти положаји клизача)</translation>
    </message>
    <message>
        <source>leg 1: other working mode (same platform position)</source>
        <translation>нога 1: други радни режим (исти положај платформе)</translation>
    </message>
    <message>
        <source>leg 2: other working mode (same platform position)</source>
        <translation>нога 2: други радни режим (исти положај платформе)</translation>
    </message>
    <message>
        <source>slider K₁</source>
        <translation>клизач K₁</translation>
    </message>
    <message>
        <source>slider K₂</source>
        <translation>клизач K₂</translation>
    </message>
    <message>
        <source>link S₁</source>
        <translation>спојка S₁</translation>
    </message>
    <message>
        <source>link S₂</source>
        <translation>спојка S₂</translation>
    </message>
    <message>
        <source>guide PO₁</source>
        <translation>вођица PO₁</translation>
    </message>
    <message>
        <source>guide PO₂</source>
        <translation>вођица PO₂</translation>
    </message>
    <message>
        <source>MOMA: two sliders on powered guides, two links meeting at the platform joint P</source>
        <translation>MOMA: два клизача на погонским вођицама и две спојке спојене у зглобу платформе P</translation>
    </message>
    <message>
        <source>drag to move the platform (inverse kinematics)</source>
        <translation>превуците да бисте померили платформу (инверзна кинематика)</translation>
    </message>
    <message>
        <source>drag along guide 1 to set p₁ (direct kinematics)</source>
        <translation>превуците дуж вођице 1 да бисте задали p₁ (директна кинематика)</translation>
    </message>
    <message>
        <source>drag along guide 2 to set p₂ (direct kinematics)</source>
        <translation>превуците дуж вођице 2 да бисте задали p₂ (директна кинематика)</translation>
    </message>
    <message>
        <source>link ⟂ guide</source>
        <translation>спојка ⟂ вођици</translation>
    </message>
    <message>
        <source>links collinear</source>
        <translation>спојке колинеарне</translation>
    </message>
    <message>
        <source>link 1 ⟂ guide 1</source>
        <translation>спојка 1 ⟂ вођици 1</translation>
    </message>
    <message>
        <source>link 2 ⟂ guide 2</source>
        <translation>спојка 2 ⟂ вођици 2</translation>
    </message>
    <message>
        <source>crossed (X)</source>
        <translation>укрштени (X)</translation>
    </message>
    <message>
        <source>extended (O)</source>
        <translation>опружени (O)</translation>
    </message>
    <message>
        <source>rod length</source>
        <translation>дужина штапа</translation>
    </message>
    <message>
        <source>platform width</source>
        <translation>ширина платформе</translation>
    </message>
    <message>
        <source>transverse guide length (slider positions 0…L)</source>
        <translation>дужина попречних вођица (положаји клизача 0…L)</translation>
    </message>
    <message>
        <source>spacing of the transverse guides</source>
        <translation>размак попречних вођица</translation>
    </message>
    <message>
        <source>start of the longitudinal travel</source>
        <translation>почетак уздужног хода</translation>
    </message>
    <message>
        <source>end of the longitudinal travel</source>
        <translation>крај уздужног хода</translation>
    </message>
    <message>
        <source>+1 extended (O), −1 crossed (X)</source>
        <translation>+1 опружени (O), −1 укрштени (X)</translation>
    </message>
    <message>
        <source>The O-X glide has no parameter named &apos;%1&apos;.</source>
        <translation>Механизам O-X glide нема параметар „%1”.</translation>
    </message>
    <message>
        <source>mode = %1 is invalid: it must be +1 (O, extended) or -1 (X, crossed).</source>
        <translation>mode = %1 није дозвољена вредност: мора бити +1 (O, опружени облик) или -1 (X, укрштени).</translation>
    </message>
    <message>
        <source>mode must be +1 (O, extended) or -1 (X, crossed).</source>
        <translation>mode мора бити +1 (O, опружени облик) или -1 (X, укрштени).</translation>
    </message>
    <message>
        <source>s = %1 must be less than 2l = %2: a platform that wide keeps the rods from ever crossing, so there is no X form.</source>
        <translation>s = %1 мора бити мање од 2l = %2: са тако широком платформом штапови се никада не укрштају, па укрштени (X) облик не постоји.</translation>
    </message>
    <message>
        <source>L = %1 must be more than the platform width s = %2: with guides that short the extended (O) form has no workspace.</source>
        <translation>L = %1 мора бити веће од ширине платформе s = %2: са тако кратким вођицама опружени (O) облик нема радни простор.</translation>
    </message>
    <message>
        <source>z_min = %1 must be less than z_max = %2.</source>
        <translation>z_min = %1 мора бити мање од z_max = %2.</translation>
    </message>
    <message>
        <source>The crossed (X) form has no workspace with L = %1, s = %2 and l = %3.</source>
        <translation>Укрштени (X) облик нема радни простор за L = %1, s = %2 и l = %3.</translation>
    </message>
    <message>
        <source>The extended (O) form has no workspace with L = %1, s = %2 and l = %3.</source>
        <translation>Опружени (O) облик нема радни простор за L = %1, s = %2 и l = %3.</translation>
    </message>
    <message>
        <source>slider pair AB position (actuated)</source>
        <translation>положај пара клизача AB (погонски)</translation>
    </message>
    <message>
        <source>slider pair CD position (actuated)</source>
        <translation>положај пара клизача CD (погонски)</translation>
    </message>
    <message>
        <source>longitudinal position (actuated serial axis)</source>
        <translation>уздужни положај (погонска серијска оса)</translation>
    </message>
    <message>
        <source>platform centre T, x</source>
        <translation>центар платформе T, x</translation>
    </message>
    <message>
        <source>platform centre T, y</source>
        <translation>центар платформе T, y</translation>
    </message>
    <message>
        <source>The platform cannot reach %1: y is more than the rod length l = %2.</source>
        <translation>Платформа не може да достигне %1: y је веће од дужине штапа l = %2.</translation>
    </message>
    <message>
        <source>The platform cannot reach %1: it would pass the rod joints&apos; plane y = 0, where the rods lie along the guides (a direct singularity).</source>
        <translation>Платформа не може да достигне %1: прешла би раван зглобова штапова y = 0, где штапови леже дуж вођица (сингуларитет директне кинематике).</translation>
    </message>
    <message>
        <source>The crossed (X) form cannot reach %1: slider pair %2 would have to be at %3 = %4, off its guides (0…%5 mm).</source>
        <translation>Укрштени (X) облик не може да достигне %1: пар клизача %2 морао би да буде на %3 = %4, ван својих вођица (0…%5 mm).</translation>
    </message>
    <message>
        <source>The extended (O) form cannot reach %1: slider pair %2 would have to be at %3 = %4, off its guides (0…%5 mm).</source>
        <translation>Опружени (O) облик не може да достигне %1: пар клизача %2 морао би да буде на %3 = %4, ван својих вођица (0…%5 mm).</translation>
    </message>
    <message>
        <source>%1 = %2 is off the guides (%3…%4 mm).</source>
        <translation>%1 = %2 је ван вођица (%3…%4 mm).</translation>
    </message>
    <message>
        <source>%1 = %2 is outside the travel (%3…%4 mm).</source>
        <translation>%1 = %2 је ван хода (%3…%4 mm).</translation>
    </message>
    <message>
        <source>The rods cannot reach the platform at x_AB = %1, x_CD = %2: |x_CD − x_AB − s| = %3 is more than 2l = %4.</source>
        <translation>Штапови не могу да досегну платформу за x_AB = %1, x_CD = %2: |x_CD − x_AB − s| = %3 је веће од 2l = %4.</translation>
    </message>
    <message>
        <source>x_CD − x_AB = %1 is less than s = %2: these slider positions hold the crossed (X) form, and the mechanism is extended (O). At x_CD − x_AB = s the rods are parallel and the platform can swing (a singularity), so the pairs do not pass it on their own: switch the form to go on.</source>
        <translation>x_CD − x_AB = %1 је мање од s = %2: ови положаји клизача одговарају укрштеном (X) облику, а механизам је у опруженом (O). За x_CD − x_AB = s штапови су паралелни и платформа може да се њише (сингуларитет), па га парови клизача сами не прелазе: промените облик да бисте наставили.</translation>
    </message>
    <message>
        <source>x_CD − x_AB = %1 is more than s = %2: these slider positions hold the extended (O) form, and the mechanism is crossed (X). At x_CD − x_AB = s the rods are parallel and the platform can swing (a singularity), so the pairs do not pass it on their own: switch the form to go on.</source>
        <translation>x_CD − x_AB = %1 је веће од s = %2: ови положаји клизача одговарају опруженом (O) облику, а механизам је у укрштеном (X). За x_CD − x_AB = s штапови су паралелни и платформа може да се њише (сингуларитет), па га парови клизача сами не прелазе: промените облик да бисте наставили.</translation>
    </message>
    <message>
        <source>slider pair AB position</source>
        <translation>положај пара клизача AB</translation>
    </message>
    <message>
        <source>slider pair CD position</source>
        <translation>положај пара клизача CD</translation>
    </message>
    <message>
        <source>longitudinal position</source>
        <translation>уздужни положај</translation>
    </message>
    <message>
        <source>J_q = diag(−2u₁, −2u₂), u_i the rods&apos; runs along the guides</source>
        <translation>J_q = diag(−2u₁, −2u₂), u_i — пројекције штапова на вођице</translation>
    </message>
    <message>
        <source>J_x rows (2u_i, 2y)</source>
        <translation>врсте J_x: (2u_i, 2y)</translation>
    </message>
    <message>
        <source>q̇ = J·ẋ of the planar part, J = −J_q⁻¹·J_x</source>
        <translation>q̇ = J·ẋ раванског дела, J = −J_q⁻¹·J_x</translation>
    </message>
    <message>
        <source>angle between the rods and the guides (90°: the O↔X crossing)</source>
        <translation>угао између штапова и вођица (90°: прелаз O↔X)</translation>
    </message>
    <message>
        <source>distance from the O↔X crossing (0 there; &gt; 0 O, &lt; 0 X)</source>
        <translation>растојање од прелаза O↔X (0 на њему; &gt; 0 O, &lt; 0 X)</translation>
    </message>
    <message>
        <source>form of the pose: O extended, X crossed</source>
        <translation>облик положаја: O опружени, X укрштени</translation>
    </message>
    <message>
        <source>crossed (X) form (same platform position)</source>
        <translation>укрштени (X) облик (исти положај платформе)</translation>
    </message>
    <message>
        <source>extended (O) form (same platform position)</source>
        <translation>опружени (O) облик (исти положај платформе)</translation>
    </message>
    <message>
        <source>rods ⟂ guides: the O↔X crossing</source>
        <translation>штапови ⟂ вођицама: прелаз O↔X</translation>
    </message>
    <message>
        <source>rods parallel: the platform can swing</source>
        <translation>штапови паралелни: платформа може да се њише</translation>
    </message>
    <message>
        <source>rods along the guides</source>
        <translation>штапови дуж вођица</translation>
    </message>
    <message>
        <source>rods ⟂ guides</source>
        <translation>штапови ⟂ вођицама</translation>
    </message>
    <message>
        <source>drag to move the platform (inverse kinematics, in the current form)</source>
        <translation>превуците да бисте померили платформу (инверзна кинематика, у тренутном облику)</translation>
    </message>
    <message>
        <source>drag along the guides to set x_AB (direct kinematics)</source>
        <translation>превуците дуж вођица да бисте задали x_AB (директна кинематика)</translation>
    </message>
    <message>
        <source>drag along the guides to set x_CD (direct kinematics)</source>
        <translation>превуците дуж вођица да бисте задали x_CD (директна кинематика)</translation>
    </message>
    <message>
        <source>longitudinal carriage</source>
        <translation>уздужна колица</translation>
    </message>
    <message>
        <source>end plate</source>
        <translation>чеона плоча</translation>
    </message>
    <message>
        <source>longitudinal guide</source>
        <translation>уздужна вођица</translation>
    </message>
    <message>
        <source>slider %1</source>
        <translation>клизач %1</translation>
    </message>
    <message>
        <source>compensation element %1</source>
        <translation>компензациони елемент %1</translation>
    </message>
    <message>
        <source>rod joint %1</source>
        <translation>зглоб штапа %1</translation>
    </message>
    <message>
        <source>pair AB</source>
        <translation>пар AB</translation>
    </message>
    <message>
        <source>pair CD</source>
        <translation>пар CD</translation>
    </message>
    <message>
        <source>rod %1</source>
        <translation>штап %1</translation>
    </message>
    <message>
        <source>spherical joint %1</source>
        <translation>сферни зглоб %1</translation>
    </message>
    <message>
        <source>carriage</source>
        <translation>колица</translation>
    </message>
    <message>
        <source>slider pair AB</source>
        <translation>пар клизача AB</translation>
    </message>
    <message>
        <source>slider pair CD</source>
        <translation>пар клизача CD</translation>
    </message>
    <message>
        <source>O-X glide: carriage on the longitudinal guides, slider pairs AB and CD, four rods (revolute at the sliders, spherical at the platform), platform</source>
        <translation>O-X glide: колица на уздужним вођицама, парови клизача AB и CD, четири штапа (обртни зглобови на клизачима, сферни на платформи), платформа</translation>
    </message>
    <message>
        <source>crank (lever) length</source>
        <translation>дужина полуге</translation>
    </message>
    <message>
        <source>base and coupler length</source>
        <translation>дужина основе и спојке</translation>
    </message>
    <message>
        <source>ratio k = b/a</source>
        <translation>однос k = b/a</translation>
    </message>
    <message>
        <source>lower limit of θ</source>
        <translation>доња граница θ</translation>
    </message>
    <message>
        <source>upper limit of θ</source>
        <translation>горња граница θ</translation>
    </message>
    <message>
        <source>lead of the screw</source>
        <translation>корак завојног вретена</translation>
    </message>
    <message>
        <source>linear step</source>
        <translation>линеарни корак</translation>
    </message>
    <message>
        <source>max. linear speed</source>
        <translation>макс. линеарна брзина</translation>
    </message>
    <message>
        <source>max. thrust force</source>
        <translation>макс. погонска сила</translation>
    </message>
    <message>
        <source>screw efficiency</source>
        <translation>степен искоришћења завојног вретена</translation>
    </message>
    <message>
        <source>motor body length</source>
        <translation>дужина кућишта мотора</translation>
    </message>
    <message>
        <source>motor body width</source>
        <translation>ширина кућишта мотора</translation>
    </message>
    <message>
        <source>screw diameter</source>
        <translation>пречник завојног вретена</translation>
    </message>
    <message>
        <source>k = b/a = %1 is out of proportion: it must lie between 1e-6 and 1e6.</source>
        <translation>k = b/a = %1 је ван сваке мере: мора бити између 1e-6 и 1e6.</translation>
    </message>
    <message>
        <source>theta_min = %1° must be less than theta_max = %2°.</source>
        <translation>theta_min = %1° мора бити мање од theta_max = %2°.</translation>
    </message>
    <message>
        <source>k = %1 and b = %2 mm both set the coupler: give b or k, not both.</source>
        <translation>k = %1 и b = %2 mm оба одређују спојку: задајте b или k, не оба.</translation>
    </message>
    <message>
        <source>The П-joint has no parameter named &apos;%1&apos;.</source>
        <translation>П-зглоб нема параметар „%1”.</translation>
    </message>
    <message>
        <source>theta_max = %1° must be greater than theta_min = %2°.</source>
        <translation>theta_max = %1° мора бити веће од theta_min = %2°.</translation>
    </message>
    <message>
        <source>The motor body (%1 mm) is longer than d_min = %2 mm: the diagonal cannot retract that far.</source>
        <translation>Кућиште мотора (%1 mm) дуже је од d_min = %2 mm: дијагонала не може толико да се скрати.</translation>
    </message>
    <message>
        <source>diagonal length (actuated)</source>
        <translation>дужина дијагонале (погонска)</translation>
    </message>
    <message>
        <source>output angle</source>
        <translation>излазни угао</translation>
    </message>
    <message>
        <source>d = %1 mm is outside the stroke [%2, %3] mm that the θ range allows.</source>
        <translation>d = %1 mm је ван хода [%2; %3] mm који допушта опсег θ.</translation>
    </message>
    <message>
        <source>θ = %1° is outside the design range [%2, %3]°.</source>
        <translation>θ = %1° је ван пројектованог опсега [%2; %3]°.</translation>
    </message>
    <message>
        <source>diagonal length</source>
        <translation>дужина дијагонале</translation>
    </message>
    <message>
        <source>passive angle of the diagonal</source>
        <translation>пасивни угао дијагонале</translation>
    </message>
    <message>
        <source>transmission angle</source>
        <translation>угао преноса</translation>
    </message>
    <message>
        <source>Jacobian ḋ = J·θ̇</source>
        <translation>Јакобијан ḋ = J·θ̇</translation>
    </message>
    <message>
        <source>inverse Jacobian θ̇ = J⁻¹·ḋ</source>
        <translation>инверзни јакобијан θ̇ = J⁻¹·ḋ</translation>
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
        <translation>извод J</translation>
    </message>
    <message>
        <source>output torque at F_max</source>
        <translation>излазни момент при F_max</translation>
    </message>
    <message>
        <source>output speed θ̇ at ḋ_max</source>
        <translation>излазна угаона брзина θ̇ при ḋ_max</translation>
    </message>
    <message>
        <source>output resolution per step</source>
        <translation>излазна резолуција по кораку</translation>
    </message>
    <message>
        <source>motor torque at F_max</source>
        <translation>момент мотора при F_max</translation>
    </message>
    <message>
        <source>diagonal at θ_min</source>
        <translation>дијагонала при θ_min</translation>
    </message>
    <message>
        <source>diagonal at θ_max</source>
        <translation>дијагонала при θ_max</translation>
    </message>
    <message>
        <source>actuator stroke</source>
        <translation>ход актуатора</translation>
    </message>
    <message>
        <source>recommended range from (J ≥ 60 % of best)</source>
        <translation>препоручени опсег: од (J ≥ 60 % највећег)</translation>
    </message>
    <message>
        <source>recommended range to (J ≥ 60 % of best)</source>
        <translation>препоручени опсег: до (J ≥ 60 % највећег)</translation>
    </message>
    <message>
        <source>motor body</source>
        <translation>кућиште мотора</translation>
    </message>
    <message>
        <source>screw</source>
        <translation>вретено</translation>
    </message>
    <message>
        <source>O (motor)</source>
        <translation>O (мотор)</translation>
    </message>
    <message>
        <source>A (screw)</source>
        <translation>A (вретено)</translation>
    </message>
    <message>
        <source>active П-joint: hinged parallelogram OBAC with the telescopic diagonal OA (motor body and screw)</source>
        <translation>активни П-зглоб: зглобни паралелограм OBAC са телескопском дијагоналом OA (кућиште мотора и вретено)</translation>
    </message>
    <message>
        <source>drag A to set θ</source>
        <translation>превуците A да бисте задали θ</translation>
    </message>
    <message>
        <source>drag C to set θ</source>
        <translation>превуците C да бисте задали θ</translation>
    </message>
    <message>
        <source>The pointer is on the pivot: θ is undefined there.</source>
        <translation>Показивач је на оси обртања: ту угао θ није одређен.</translation>
    </message>
    <message>
        <source>Active П-joint</source>
        <translation>Активни П-зглоб</translation>
    </message>
    <message>
        <source>MOMA 2-axis parallel mechanism</source>
        <translation>Двоосни паралелни механизам MOMA</translation>
    </message>
    <message>
        <source>O-X glide hybrid mechanism</source>
        <translation>Хибридни механизам O-X glide</translation>
    </message>
    <message>
        <source>Planar four-bar linkage</source>
        <translation>Равански зглобни четвороугао</translation>
    </message>
    <message>
        <source>Planar five-bar linkage</source>
        <translation>Равански зглобни петочлани механизам</translation>
    </message>
    <message>
        <source>Unknown mechanism kind &apos;%1&apos;.</source>
        <translation>Непознат тип механизма „%1”.</translation>
    </message>
    <message>
        <source>A %1 has no parameter named &apos;%2&apos;.</source>
        <translation>Механизам „%1” нема параметар „%2”.</translation>
    </message>
    <message>
        <source>link</source>
        <translation>члан</translation>
    </message>
    <message>
        <source>motor</source>
        <translation>мотор</translation>
    </message>
    <message>
        <source>motor %1</source>
        <translation>мотор %1</translation>
    </message>
    <message>
        <source>screw %1</source>
        <translation>вретено %1</translation>
    </message>
    <message>
        <source>guide</source>
        <translation>вођица</translation>
    </message>
    <message>
        <source>end stop %1</source>
        <translation>граничник %1</translation>
    </message>
    <message>
        <source>slider</source>
        <translation>клизач</translation>
    </message>
    <message>
        <source>support</source>
        <translation>ослонац</translation>
    </message>
    <message>
        <source>support %1</source>
        <translation>ослонац %1</translation>
    </message>
    <message>
        <source>point</source>
        <translation>тачка</translation>
    </message>
    <message>
        <source>point %1</source>
        <translation>тачка %1</translation>
    </message>
    <message>
        <source>joint</source>
        <translation>зглоб</translation>
    </message>
    <message>
        <source>joint %1</source>
        <translation>зглоб %1</translation>
    </message>
    <message>
        <source>one side</source>
        <translation>једна страна</translation>
    </message>
    <message>
        <source>form</source>
        <translation>облик</translation>
    </message>
    <message>
        <source>input of leg 1</source>
        <translation>улаз ноге 1</translation>
    </message>
    <message>
        <source>input of leg 2</source>
        <translation>улаз ноге 2</translation>
    </message>
    <message>
        <source>input of leg 3</source>
        <translation>улаз ноге 3</translation>
    </message>
    <message>
        <source>platform angle</source>
        <translation>угао платформе</translation>
    </message>
    <message>
        <source>J_q = diag(∂g_i/∂q_i)</source>
        <translation>J_q = диаг(∂g_i/∂q_i)</translation>
    </message>
    <message>
        <source>J_x rows −∂g_i/∂X</source>
        <translation>врсте J_x: −∂g_i/∂X</translation>
    </message>
    <message>
        <source>q̇ = J·Ẋ, J = J_q⁻¹·J_x</source>
        <translation>q̇ = J·Ẋ, J = J_q⁻¹·J_x</translation>
    </message>
    <message>
        <source>other assembly mode (same inputs)</source>
        <translation>други начин склапања (исти улази)</translation>
    </message>
    <message>
        <source>leg 1: other working mode (same platform pose)</source>
        <translation>нога 1: други радни режим (иста поза платформе)</translation>
    </message>
    <message>
        <source>leg 2: other working mode (same platform pose)</source>
        <translation>нога 2: други радни режим (иста поза платформе)</translation>
    </message>
    <message>
        <source>leg 3: other working mode (same platform pose)</source>
        <translation>нога 3: други радни режим (иста поза платформе)</translation>
    </message>
    <message>
        <source>%1 = %2 is invalid: it must be a whole number.</source>
        <translation>%1 = %2 није допуштено: мора бити цео број.</translation>
    </message>
    <message>
        <source>The planar parallel mechanism has no parameter named &apos;%1&apos;.</source>
        <translation>Равански паралелни механизам нема параметар „%1”.</translation>
    </message>
    <message>
        <source>platform: 0 a point (2 DOF), 1 constant orientation (2 DOF), 2 free (3 DOF)</source>
        <translation>платформа: 0 тачка (2 степена слободе), 1 стална оријентација (2 степена слободе), 2 слободна (3 степена слободе)</translation>
    </message>
    <message>
        <source>leg 1: type (0 R̲RR, 1 P̲RR, 2 RP̲R, 3 П̲RR)</source>
        <translation>нога 1: тип (0 R̲RR, 1 P̲RR, 2 RP̲R, 3 П̲RR)</translation>
    </message>
    <message>
        <source>leg 1: base point A₁, x</source>
        <translation>нога 1: тачка основе A₁, x</translation>
    </message>
    <message>
        <source>leg 1: base point A₁, y</source>
        <translation>нога 1: тачка основе A₁, y</translation>
    </message>
    <message>
        <source>leg 1: platform point B₁ in the platform frame, x</source>
        <translation>нога 1: тачка платформе B₁ у систему платформе, x</translation>
    </message>
    <message>
        <source>leg 1: platform point B₁ in the platform frame, y</source>
        <translation>нога 1: тачка платформе B₁ у систему платформе, y</translation>
    </message>
    <message>
        <source>leg 1: crank length (R̲RR)</source>
        <translation>нога 1: дужина полуге (R̲RR)</translation>
    </message>
    <message>
        <source>leg 1: distal link length</source>
        <translation>нога 1: дужина дисталне спојке</translation>
    </message>
    <message>
        <source>leg 1: direction of the guide (P̲RR) or of the П-joint base (П̲RR)</source>
        <translation>нога 1: правац вођице (P̲RR) или основе П-зглоба (П̲RR)</translation>
    </message>
    <message>
        <source>leg 1: П-joint crank (lever) length</source>
        <translation>нога 1: дужина полуге П-зглоба</translation>
    </message>
    <message>
        <source>leg 1: П-joint ratio k = b/a</source>
        <translation>нога 1: однос П-зглоба k = b/a</translation>
    </message>
    <message>
        <source>leg 1: working mode (+1 elbow left of A₁→P₁; P̲RR: sign in q = B ± √…)</source>
        <translation>нога 1: радни режим (+1 лакат лево од A₁→P₁; P̲RR: знак у q = B ± √…)</translation>
    </message>
    <message>
        <source>leg 2: type (0 R̲RR, 1 P̲RR, 2 RP̲R, 3 П̲RR)</source>
        <translation>нога 2: тип (0 R̲RR, 1 P̲RR, 2 RP̲R, 3 П̲RR)</translation>
    </message>
    <message>
        <source>leg 2: base point A₂, x</source>
        <translation>нога 2: тачка основе A₂, x</translation>
    </message>
    <message>
        <source>leg 2: base point A₂, y</source>
        <translation>нога 2: тачка основе A₂, y</translation>
    </message>
    <message>
        <source>leg 2: platform point B₂ in the platform frame, x</source>
        <translation>нога 2: тачка платформе B₂ у систему платформе, x</translation>
    </message>
    <message>
        <source>leg 2: platform point B₂ in the platform frame, y</source>
        <translation>нога 2: тачка платформе B₂ у систему платформе, y</translation>
    </message>
    <message>
        <source>leg 2: crank length (R̲RR)</source>
        <translation>нога 2: дужина полуге (R̲RR)</translation>
    </message>
    <message>
        <source>leg 2: distal link length</source>
        <translation>нога 2: дужина дисталне спојке</translation>
    </message>
    <message>
        <source>leg 2: direction of the guide (P̲RR) or of the П-joint base (П̲RR)</source>
        <translation>нога 2: правац вођице (P̲RR) или основе П-зглоба (П̲RR)</translation>
    </message>
    <message>
        <source>leg 2: П-joint crank (lever) length</source>
        <translation>нога 2: дужина полуге П-зглоба</translation>
    </message>
    <message>
        <source>leg 2: П-joint ratio k = b/a</source>
        <translation>нога 2: однос П-зглоба k = b/a</translation>
    </message>
    <message>
        <source>leg 2: working mode (+1 elbow left of A₂→P₂; P̲RR: sign in q = B ± √…)</source>
        <translation>нога 2: радни режим (+1 лакат лево од A₂→P₂; P̲RR: знак у q = B ± √…)</translation>
    </message>
    <message>
        <source>leg 3: type (0 R̲RR, 1 P̲RR, 2 RP̲R, 3 П̲RR)</source>
        <translation>нога 3: тип (0 R̲RR, 1 P̲RR, 2 RP̲R, 3 П̲RR)</translation>
    </message>
    <message>
        <source>leg 3: base point A₃, x</source>
        <translation>нога 3: тачка основе A₃, x</translation>
    </message>
    <message>
        <source>leg 3: base point A₃, y</source>
        <translation>нога 3: тачка основе A₃, y</translation>
    </message>
    <message>
        <source>leg 3: platform point B₃ in the platform frame, x</source>
        <translation>нога 3: тачка платформе B₃ у систему платформе, x</translation>
    </message>
    <message>
        <source>leg 3: platform point B₃ in the platform frame, y</source>
        <translation>нога 3: тачка платформе B₃ у систему платформе, y</translation>
    </message>
    <message>
        <source>leg 3: crank length (R̲RR)</source>
        <translation>нога 3: дужина полуге (R̲RR)</translation>
    </message>
    <message>
        <source>leg 3: distal link length</source>
        <translation>нога 3: дужина дисталне спојке</translation>
    </message>
    <message>
        <source>leg 3: direction of the guide (P̲RR) or of the П-joint base (П̲RR)</source>
        <translation>нога 3: правац вођице (P̲RR) или основе П-зглоба (П̲RR)</translation>
    </message>
    <message>
        <source>leg 3: П-joint crank (lever) length</source>
        <translation>нога 3: дужина полуге П-зглоба</translation>
    </message>
    <message>
        <source>leg 3: П-joint ratio k = b/a</source>
        <translation>нога 3: однос П-зглоба k = b/a</translation>
    </message>
    <message>
        <source>leg 3: working mode (+1 elbow left of A₃→P₃; P̲RR: sign in q = B ± √…)</source>
        <translation>нога 3: радни режим (+1 лакат лево од A₃→P₃; P̲RR: знак у q = B ± √…)</translation>
    </message>
    <message>
        <source>assembly mode: 2 DOF +1 platform left of C₁→C₂, −1 right; 3 DOF the n-th solution in order of φ</source>
        <translation>начин склапања: за 2 степена слободе +1 платформа лево од C₁→C₂, −1 десно; за 3 — n-то решење по растућем φ</translation>
    </message>
    <message>
        <source>platform angle φ of the workspace map (3 DOF)</source>
        <translation>угао платформе φ за мапу радног простора (3 степена слободе)</translation>
    </message>
    <message>
        <source>%1 must be less than %2.</source>
        <translation>%1 мора бити мање од %2.</translation>
    </message>
    <message>
        <source>The range of crank %1 spans more than one turn (360°).</source>
        <translation>Опсег полуге %1 већи је од једног обрта (360°).</translation>
    </message>
    <message>
        <source>%1 must be positive: it is the length of strut %2.</source>
        <translation>%1 мора бити позитивно: то је дужина шипке %2.</translation>
    </message>
    <message>
        <source>The diagonal of П-joint %1 must stay strictly between %2 mm and %3 mm (θ between −90° and 90°).</source>
        <translation>Дијагонала П-зглоба %1 мора бити строго између %2 мм и %3 мм (θ између −90° и 90°).</translation>
    </message>
    <message>
        <source>A platform of constant orientation needs P̲RR or П̲RR legs: leg %1&apos;s distal parallelogram must hang from a body that does not turn.</source>
        <translation>Платформи сталне оријентације потребне су ноге P̲RR или П̲RR: дистални паралелограм ноге %1 мора висити о телу које се не окреће.</translation>
    </message>
    <message>
        <source>The assembly mode of a 3-DOF platform counts the solutions from 1.</source>
        <translation>Начин склапања платформе са 3 степена слободе броји решења од 1.</translation>
    </message>
    <message>
        <source>The platform points B₁, B₂, B₃ coincide: the platform&apos;s angle is undetermined.</source>
        <translation>Тачке платформе B₁, B₂, B₃ се поклапају: угао платформе није одређен.</translation>
    </message>
    <message>
        <source>The mechanism cannot be assembled anywhere in its input ranges and modes.</source>
        <translation>Механизам се не може склопити нигде у својим опсезима улаза и режимима.</translation>
    </message>
    <message>
        <source>input of leg 1 (actuated)</source>
        <translation>улаз ноге 1 (погонски)</translation>
    </message>
    <message>
        <source>input of leg 2 (actuated)</source>
        <translation>улаз ноге 2 (погонски)</translation>
    </message>
    <message>
        <source>input of leg 3 (actuated)</source>
        <translation>улаз ноге 3 (погонски)</translation>
    </message>
    <message>
        <source>The number of inputs does not match the legs.</source>
        <translation>Број улаза не одговара броју ногу.</translation>
    </message>
    <message>
        <source>%1 = %2 is outside its range [%3, %4].</source>
        <translation>%1 = %2 је изван свог опсега [%3, %4].</translation>
    </message>
    <message>
        <source>The П-joint of leg %1 cannot take the diagonal %2 = %3 mm.</source>
        <translation>П-зглоб ноге %1 не може имати дијагоналу %2 = %3 мм.</translation>
    </message>
    <message>
        <source>The legs cannot be assembled at these inputs in the design&apos;s working and assembly modes.</source>
        <translation>При овим улазима ноге се не могу склопити у радним режимима и начину склапања пројекта.</translation>
    </message>
    <message>
        <source>At these inputs the platform has %1 assembly modes in the design&apos;s working modes, fewer than assembly = %2.</source>
        <translation>При овим улазима платформа има %1 начина склапања у радним режимима пројекта, мање од assembly = %2.</translation>
    </message>
    <message>
        <source>(%1, %2) mm, φ = %3°</source>
        <translation>(%1, %2) мм, φ = %3°</translation>
    </message>
    <message>
        <source>The platform cannot reach %1 in this assembly mode: the legs would pass through a direct singularity; switch the assembly mode to go on.</source>
        <translation>Платформа не може достићи %1 у овом начину склапања: ноге би прошле кроз сингуларитет директне кинематике; промените начин склапања да бисте наставили.</translation>
    </message>
    <message>
        <source>the input of leg %1 would leave its range</source>
        <translation>улаз ноге %1 изашао би из свог опсега</translation>
    </message>
    <message>
        <source>the input of leg %1 is undetermined there</source>
        <translation>улаз ноге %1 ту није одређен</translation>
    </message>
    <message>
        <source>leg %1 cannot reach it</source>
        <translation>нога %1 не може да је достигне</translation>
    </message>
    <message>
        <source>a leg&apos;s proximal and distal links in line</source>
        <translation>проксимална и дистална спојка ноге у линији</translation>
    </message>
    <message>
        <source>the platform gains a freedom</source>
        <translation>платформа добија слободу</translation>
    </message>
    <message>
        <source>crank %1</source>
        <translation>полуга %1</translation>
    </message>
    <message>
        <source>strut %1, motor body</source>
        <translation>шипка %1, кућиште мотора</translation>
    </message>
    <message>
        <source>strut %1, rod</source>
        <translation>шипка %1, клип</translation>
    </message>
    <message>
        <source>П-joint %1: crank OC</source>
        <translation>П-зглоб %1: полуга OC</translation>
    </message>
    <message>
        <source>П-joint %1: coupler</source>
        <translation>П-зглоб %1: спојка</translation>
    </message>
    <message>
        <source>П-joint %1: motor body</source>
        <translation>П-зглоб %1: кућиште мотора</translation>
    </message>
    <message>
        <source>П-joint %1: screw</source>
        <translation>П-зглоб %1: вретено</translation>
    </message>
    <message>
        <source>link %1, parallel</source>
        <translation>спојка %1, паралелна</translation>
    </message>
    <message>
        <source>planar parallel mechanism: legs from the leg library joined at the platform</source>
        <translation>равански паралелни механизам: ноге из библиотеке ногу спојене платформом</translation>
    </message>
    <message>
        <source>Planar parallel mechanism (leg library)</source>
        <translation>Равански паралелни механизам (библиотека ногу)</translation>
    </message>
    <message>
        <source>leg 1: lower limit of the input (P̲RR, RP̲R, П̲RR)</source>
        <translation>нога 1: доња граница улаза (P̲RR, RP̲R, П̲RR)</translation>
    </message>
    <message>
        <source>leg 1: upper limit of the input (P̲RR, RP̲R, П̲RR)</source>
        <translation>нога 1: горња граница улаза (P̲RR, RP̲R, П̲RR)</translation>
    </message>
    <message>
        <source>leg 1: lower limit of the crank angle (R̲RR)</source>
        <translation>нога 1: доња граница угла полуге (R̲RR)</translation>
    </message>
    <message>
        <source>leg 1: upper limit of the crank angle (R̲RR)</source>
        <translation>нога 1: горња граница угла полуге (R̲RR)</translation>
    </message>
    <message>
        <source>leg 2: lower limit of the input (P̲RR, RP̲R, П̲RR)</source>
        <translation>нога 2: доња граница улаза (P̲RR, RP̲R, П̲RR)</translation>
    </message>
    <message>
        <source>leg 2: upper limit of the input (P̲RR, RP̲R, П̲RR)</source>
        <translation>нога 2: горња граница улаза (P̲RR, RP̲R, П̲RR)</translation>
    </message>
    <message>
        <source>leg 2: lower limit of the crank angle (R̲RR)</source>
        <translation>нога 2: доња граница угла полуге (R̲RR)</translation>
    </message>
    <message>
        <source>leg 2: upper limit of the crank angle (R̲RR)</source>
        <translation>нога 2: горња граница угла полуге (R̲RR)</translation>
    </message>
    <message>
        <source>leg 3: lower limit of the input (P̲RR, RP̲R, П̲RR)</source>
        <translation>нога 3: доња граница улаза (P̲RR, RP̲R, П̲RR)</translation>
    </message>
    <message>
        <source>leg 3: upper limit of the input (P̲RR, RP̲R, П̲RR)</source>
        <translation>нога 3: горња граница улаза (P̲RR, RP̲R, П̲RR)</translation>
    </message>
    <message>
        <source>leg 3: lower limit of the crank angle (R̲RR)</source>
        <translation>нога 3: доња граница угла полуге (R̲RR)</translation>
    </message>
    <message>
        <source>leg 3: upper limit of the crank angle (R̲RR)</source>
        <translation>нога 3: горња граница угла полуге (R̲RR)</translation>
    </message>
    <message>
        <source>The drag stops short of the O↔X crossing at x_CD − x_AB = s = %1 mm, where the rods are parallel and the platform can swing: switch the form to go on.</source>
        <translation>Превлачење се зауставља пре прелаза O↔X при x_CD − x_AB = s = %1 mm, где су шипке паралелне и платформа може да се њише: промените облик да бисте наставили.</translation>
    </message>
    <message>
        <source>eq. %1 of the П-joint document</source>
        <translation>јед. %1 рада о П-зглобу</translation>
    </message>
    <message>
        <source>fig. %1 of the П-joint document</source>
        <translation>сл. %1 рада о П-зглобу</translation>
    </message>
    <message>
        <source>the П-joint document</source>
        <translation>рад о П-зглобу</translation>
    </message>
    <message>
        <source>eq. %1 of the MOMA document</source>
        <translation>јед. %1 рада о MOMA</translation>
    </message>
    <message>
        <source>fig. %1 of the MOMA document</source>
        <translation>сл. %1 рада о MOMA</translation>
    </message>
    <message>
        <source>the MOMA document</source>
        <translation>рад о MOMA</translation>
    </message>
    <message>
        <source>eq. %1 of the O-X glide document</source>
        <translation>јед. %1 рада о O-X glide</translation>
    </message>
    <message>
        <source>fig. %1 of the O-X glide document</source>
        <translation>сл. %1 рада о O-X glide</translation>
    </message>
    <message>
        <source>the O-X glide document</source>
        <translation>рад о O-X glide</translation>
    </message>
    <message>
        <source>eq. %1 of the four-bar and mobility document</source>
        <translation>јед. %1 рада о зглобном четвороуглу и покретљивости</translation>
    </message>
    <message>
        <source>fig. %1 of the four-bar and mobility document</source>
        <translation>сл. %1 рада о зглобном четвороуглу и покретљивости</translation>
    </message>
    <message>
        <source>the four-bar and mobility document</source>
        <translation>рад о зглобном четвороуглу и покретљивости</translation>
    </message>
    <message>
        <source>PKM Studio&apos;s model</source>
        <translation>модел програма PKM Studio</translation>
    </message>
    <message>
        <source>Input Jacobian of leg 1 (0: inverse singularity)</source>
        <translation>Јакобијан улаза ноге 1 (0: сингуларитет инверзне кинематике)</translation>
    </message>
    <message>
        <source>Input Jacobian of leg 2 (0: inverse singularity)</source>
        <translation>Јакобијан улаза ноге 2 (0: сингуларитет инверзне кинематике)</translation>
    </message>
    <message>
        <source>Output Jacobian (0: direct singularity)</source>
        <translation>Јакобијан излаза (0: сингуларитет директне кинематике)</translation>
    </message>
    <message>
        <source>Determinant of J</source>
        <translation>Детерминанта J</translation>
    </message>
    <message>
        <source>J = J_q⁻¹·J_x maps lengths to angles, so det J is in rad²/mm², not dimensionless as MOMA&apos;s and the O-X glide&apos;s.</source>
        <translation>J = J_q⁻¹·J_x пресликава дужине у углове, па је det J у rad²/mm², а не бездимензионалан као код MOMA и O-X glide.</translation>
    </message>
    <message>
        <source>Transmission angle between the distal links</source>
        <translation>Угао преноса између спојки</translation>
    </message>
    <message>
        <source>Distance from the inverse singularities</source>
        <translation>Удаљеност од сингуларитета инверзне кинематике</translation>
    </message>
    <message>
        <source>Distance from the direct singularities</source>
        <translation>Удаљеност од сингуларитета директне кинематике</translation>
    </message>
    <message>
        <source>Transmission angle γ at C</source>
        <translation>Угао преноса γ у C</translation>
    </message>
    <message>
        <source>Angle at D from DA to DB</source>
        <translation>Угао у D од DA до DB</translation>
    </message>
    <message>
        <source>Rocker angle</source>
        <translation>Угао клацкалице</translation>
    </message>
    <message>
        <source>The document takes the arctan of the ratio, which is 180° off wherever CD − BC·cos γ &lt; 0; the program uses atan2.</source>
        <translation>Рад узима arctg количника, што греши за 180° где год је CD − BC·cos γ &lt; 0; програм користи atan2.</translation>
    </message>
    <message>
        <source>Angle at B</source>
        <translation>Угао у B</translation>
    </message>
    <message>
        <source>Transfer function dδ/dα</source>
        <translation>Преносна функција dδ/dα</translation>
    </message>
    <message>
        <source>The document&apos;s (8) and (9) give the rocker&apos;s counter-clockwise rate dθ₃/dt = −dδ/dt; the program&apos;s ω₃ and i₃₁ are their negatives.</source>
        <translation>Једначине (8) и (9) из рада дају брзину клацкалице супротно од казаљке на сату dθ₃/dt = −dδ/dt; ω₃ и i₃₁ у програму су исте величине са супротним знаком.</translation>
    </message>
    <message>
        <source>Rocker angular velocity</source>
        <translation>Угаона брзина клацкалице</translation>
    </message>
    <message>
        <source>Rocker angular acceleration at constant ω₁</source>
        <translation>Угаоно убрзање клацкалице при константној ω₁</translation>
    </message>
    <message>
        <source>The document&apos;s (14) agrees with neither sign of the exact second derivative; the program differentiates the loop closure twice.</source>
        <translation>Једначина (14) из рада се не слаже са тачним другим изводом ни са једним знаком; програм двапут диференцира једначину затварања контуре.</translation>
    </message>
    <message>
        <source>Input Jacobian (0: inverse singularity)</source>
        <translation>Јакобијан улаза (0: сингуларитет инверзне кинематике)</translation>
    </message>
    <message>
        <source>Projection on guide %1</source>
        <translation>Пројекција на вођицу %1</translation>
    </message>
    <message>
        <source>Reach of link %1</source>
        <translation>Домет спојке %1</translation>
    </message>
    <message>
        <source>Inverse kinematics of leg %1</source>
        <translation>Инверзна кинематика ноге %1</translation>
    </message>
    <message>
        <source>The program takes B_i² − C_i as l_i² − (a_i × (P − R_i))², the same number without cancelling two large ones.</source>
        <translation>Програм рачуна B_i² − C_i као l_i² − (a_i × (P − R_i))²: исти број, без одузимања два велика броја.</translation>
    </message>
    <message>
        <source>Direct kinematics: P along Z₁→Z₂</source>
        <translation>Директна кинематика: P дуж Z₁→Z₂</translation>
    </message>
    <message>
        <source>The document&apos;s (10–12) divide by x_Z2 − x_Z1 and fail with the slider joints one above the other; the program intersects the circles measured along Z₁→Z₂: P = Z₁ + s·u + σ·h·n, h = √(l₁² − s²).</source>
        <translation>Једначине (10–12) из рада деле са x_Z2 − x_Z1 и не важе кад су зглобови клизача један изнад другог; програм сече кругове мерећи дуж Z₁→Z₂: P = Z₁ + s·u + σ·h·n, h = √(l₁² − s²).</translation>
    </message>
    <message>
        <source>From J_p·ṗ + J_x·Ṗ = 0 the program&apos;s J is −J_p⁻¹·J_x; the document&apos;s (21) has no minus sign. For the 2×2 J the determinant is the same.</source>
        <translation>Из J_p·ṗ + J_x·Ṗ = 0 у програму је J = −J_p⁻¹·J_x; у једначини (21) из рада нема минуса. За матрицу J 2×2 детерминанта је иста.</translation>
    </message>
    <message>
        <source>Run of a rod along the guides</source>
        <translation>Пројекција шипке дуж вођица</translation>
    </message>
    <message>
        <source>Inverse kinematics, %1 form</source>
        <translation>Инверзна кинематика, облик %1</translation>
    </message>
    <message>
        <source>Direct kinematics, both forms</source>
        <translation>Директна кинематика, оба облика</translation>
    </message>
    <message>
        <source>The document prints “+ s” in the X form&apos;s direct kinematics, which contradicts its own inverse kinematics; with “− s” both forms return their poses exactly. The sign of x_CD − x_AB − s is the form.</source>
        <translation>Рад у директној кинематици облика X штампа „+ s”, што противречи његовој инверзној кинематици; са „− s” оба облика тачно враћају своје положаје. Знак x_CD − x_AB − s је облик.</translation>
    </message>
    <message>
        <source>J = −J_q⁻¹·J_x = [1, y/u₁; 1, y/u₂] from the constraints (x ∓ s/2 − x_i)² + y² − l² = 0; w = 0 (rods perpendicular to the guides or parallel to each other) is singular.</source>
        <translation>J = −J_q⁻¹·J_x = [1, y/u₁; 1, y/u₂] из једначина веза (x ∓ s/2 − x_i)² + y² − l² = 0; w = 0 (шипке управне на вођице или паралелне међусобно) је сингуларитет.</translation>
    </message>
    <message>
        <source>Condition number of J</source>
        <translation>Број условљености J</translation>
    </message>
    <message>
        <source>Inverse kinematics</source>
        <translation>Инверзна кинематика</translation>
    </message>
    <message>
        <source>Direct kinematics</source>
        <translation>Директна кинематика</translation>
    </message>
    <message>
        <source>Transmission angle</source>
        <translation>Угао преноса</translation>
    </message>
    <message>
        <source>Output torque at F_max</source>
        <translation>Излазни момент при F_max</translation>
    </message>
    <message>
        <source>J in mm/rad times F in N gives N·mm; 10⁻³ turns it into N·m.</source>
        <translation>J у mm/rad пута F у N даје N·mm; чинилац 10⁻³ претвара то у N·m.</translation>
    </message>
    <message>
        <source>Output resolution per motor step</source>
        <translation>Излазна резолуција по кораку мотора</translation>
    </message>
    <message>
        <source>Motor torque at F_max</source>
        <translation>Момент мотора при F_max</translation>
    </message>
    <message>
        <source>Table 1 gives no screw efficiency η; the presets assume 0.4.</source>
        <translation>Табела 1 не даје степен искоришћења вретена η; примери узимају 0,4.</translation>
    </message>
    <message>
        <source>The document&apos;s acceleration (19–20) drops θ̈ from the first term and writes θ̇ where θ̇² belongs; the program uses d̈ = J·θ̈ + (∂J/∂θ)·θ̇², which agrees with the numerical second derivative.</source>
        <translation>У убрзању (19–20) из рада првом члану недостаје θ̈, а уместо θ̇² пише θ̇; програм користи d̈ = J·θ̈ + (∂J/∂θ)·θ̇², што се слаже са нумеричким другим изводом.</translation>
    </message>
    <message>
        <source>At the platform&apos;s position %1 the legs would hold it only in the other assembly mode.</source>
        <translation>У положају платформе %1 ноге би је држале само у другом начину склапања.</translation>
    </message>
    <message>
        <source>At the platform&apos;s position %1 leg %2 cannot reach it: its platform point is too far from its base point A%2 for its links.</source>
        <translation>У положају платформе %1 нога %2 не може да је достигне: њена тачка платформе је предалеко од тачке основе A%2 за њене чланове.</translation>
    </message>
    <message>
        <source>At the platform&apos;s position %1 leg %2 cannot reach it: its platform point is too near its base point A%2 for its links.</source>
        <translation>У положају платформе %1 нога %2 не може да је достигне: њена тачка платформе је преблизу тачки основе A%2 за њене чланове.</translation>
    </message>
    <message>
        <source>At the platform&apos;s position %1 leg %2 cannot reach it: its input would leave its range.</source>
        <translation>У положају платформе %1 нога %2 не може да је достигне: њен улаз изашао би из свог опсега.</translation>
    </message>
    <message>
        <source>At the platform&apos;s position %1 the input of leg %2 is undetermined.</source>
        <translation>У положају платформе %1 улаз ноге %2 није одређен.</translation>
    </message>
    <message>
        <source>drag to move the base point A%1 (changes the design)</source>
        <translation>превуците да померите тачку основе A%1 (мења конструкцију)</translation>
    </message>
    <message>
        <source>drag to move the platform point B%1 (changes the design)</source>
        <translation>превуците да померите тачку платформе B%1 (мења конструкцију)</translation>
    </message>
    <message>
        <source>Leg %1 (%2): constraint</source>
        <translation>Нога %1 (%2): једначина везе</translation>
    </message>
    <message>
        <source>Leg %1 (%2): the П-joint&apos;s angle</source>
        <translation>Нога %1 (%2): угао П-зглоба</translation>
    </message>
    <message>
        <source>Leg %1 (%2): the П-joint&apos;s Jacobian</source>
        <translation>Нога %1 (%2): јакобијан П-зглоба</translation>
    </message>
    <message>
        <source>The leg&apos;s row of J_x carries this J as a factor, so the П-joint&apos;s own singularity (θ = ±90°) is a direct singularity of the whole mechanism (the П-joint document, section 4).</source>
        <translation>Ред ноге у J_x садржи овај J као чинилац, па је сингуларитет самог П-зглоба (θ = ±90°) сингуларитет директне кинематике целог механизма (рад о П-зглобу, одељак 4).</translation>
    </message>
    <message>
        <source>Leg %1 (%2): input Jacobian (0: inverse singularity)</source>
        <translation>Нога %1 (%2): јакобијан улаза (0: сингуларитет инверзне кинематике)</translation>
    </message>
    <message>
        <source>assembly mode 1 (same inputs)</source>
        <translation>начин склапања 1 (исти улази)</translation>
    </message>
    <message>
        <source>assembly mode 2 (same inputs)</source>
        <translation>начин склапања 2 (исти улази)</translation>
    </message>
    <message>
        <source>assembly mode 3 (same inputs)</source>
        <translation>начин склапања 3 (исти улази)</translation>
    </message>
    <message>
        <source>assembly mode 4 (same inputs)</source>
        <translation>начин склапања 4 (исти улази)</translation>
    </message>
    <message>
        <source>assembly mode 5 (same inputs)</source>
        <translation>начин склапања 5 (исти улази)</translation>
    </message>
    <message>
        <source>assembly mode 6 (same inputs)</source>
        <translation>начин склапања 6 (исти улази)</translation>
    </message>
    <message>
        <source>leg 1 stretched (crank and link in line)</source>
        <translation>нога 1 опружена (полуга и спојка на истој правој)</translation>
    </message>
    <message>
        <source>leg 1 folded (crank and link in line)</source>
        <translation>нога 1 пресавијена (полуга и спојка на истој правој)</translation>
    </message>
    <message>
        <source>leg 2 stretched (crank and link in line)</source>
        <translation>нога 2 опружена (полуга и спојка на истој правој)</translation>
    </message>
    <message>
        <source>leg 2 folded (crank and link in line)</source>
        <translation>нога 2 пресавијена (полуга и спојка на истој правој)</translation>
    </message>
    <message>
        <source>leg 3 stretched (crank and link in line)</source>
        <translation>нога 3 опружена (полуга и спојка на истој правој)</translation>
    </message>
    <message>
        <source>leg 3 folded (crank and link in line)</source>
        <translation>нога 3 пресавијена (полуга и спојка на истој правој)</translation>
    </message>
    <message>
        <source>link 3 ⟂ guide 3</source>
        <translation>спојка 3 ⟂ вођици 3</translation>
    </message>
    <message>
        <source>distal lines through one point</source>
        <translation>дисталне праве кроз једну тачку</translation>
    </message>
    <message>
        <source>actuator 1: maximum force</source>
        <translation>погон 1: највећа сила</translation>
    </message>
    <message>
        <source>actuator 2: maximum force</source>
        <translation>погон 2: највећа сила</translation>
    </message>
    <message>
        <source>actuator 3: maximum force</source>
        <translation>погон 3: највећа сила</translation>
    </message>
    <message>
        <source>actuator 1: maximum speed</source>
        <translation>погон 1: највећа брзина</translation>
    </message>
    <message>
        <source>actuator 2: maximum speed</source>
        <translation>погон 2: највећа брзина</translation>
    </message>
    <message>
        <source>actuator 3: maximum speed</source>
        <translation>погон 3: највећа брзина</translation>
    </message>
    <message>
        <source>actuator 1: step (resolution)</source>
        <translation>погон 1: корак (резолуција)</translation>
    </message>
    <message>
        <source>actuator 2: step (resolution)</source>
        <translation>погон 2: корак (резолуција)</translation>
    </message>
    <message>
        <source>actuator 3: step (resolution)</source>
        <translation>погон 3: корак (резолуција)</translation>
    </message>
    <message>
        <source>actuator 1: axial stiffness</source>
        <translation>погон 1: аксијална крутост</translation>
    </message>
    <message>
        <source>actuator 2: axial stiffness</source>
        <translation>погон 2: аксијална крутост</translation>
    </message>
    <message>
        <source>actuator 3: axial stiffness</source>
        <translation>погон 3: аксијална крутост</translation>
    </message>
    <message>
        <source>actuator 1: maximum torque</source>
        <translation>погон 1: највећи момент</translation>
    </message>
    <message>
        <source>actuator 2: maximum torque</source>
        <translation>погон 2: највећи момент</translation>
    </message>
    <message>
        <source>actuator 3: maximum torque</source>
        <translation>погон 3: највећи момент</translation>
    </message>
    <message>
        <source>actuator 1: maximum angular speed</source>
        <translation>погон 1: највећа угаона брзина</translation>
    </message>
    <message>
        <source>actuator 2: maximum angular speed</source>
        <translation>погон 2: највећа угаона брзина</translation>
    </message>
    <message>
        <source>actuator 3: maximum angular speed</source>
        <translation>погон 3: највећа угаона брзина</translation>
    </message>
    <message>
        <source>actuator 1: angular step (resolution)</source>
        <translation>погон 1: угаони корак (резолуција)</translation>
    </message>
    <message>
        <source>actuator 2: angular step (resolution)</source>
        <translation>погон 2: угаони корак (резолуција)</translation>
    </message>
    <message>
        <source>actuator 3: angular step (resolution)</source>
        <translation>погон 3: угаони корак (резолуција)</translation>
    </message>
    <message>
        <source>actuator 1: torsional stiffness</source>
        <translation>погон 1: торзиона крутост</translation>
    </message>
    <message>
        <source>actuator 2: torsional stiffness</source>
        <translation>погон 2: торзиона крутост</translation>
    </message>
    <message>
        <source>actuator 3: torsional stiffness</source>
        <translation>погон 3: торзиона крутост</translation>
    </message>
    <message>
        <source>largest force in the weakest direction</source>
        <translation>највећа сила у најслабијем правцу</translation>
    </message>
    <message>
        <source>largest force in the strongest direction</source>
        <translation>највећа сила у најјачем правцу</translation>
    </message>
    <message>
        <source>largest speed in the slowest direction</source>
        <translation>највећа брзина у најспоријем правцу</translation>
    </message>
    <message>
        <source>largest speed in the fastest direction</source>
        <translation>највећа брзина у најбржем правцу</translation>
    </message>
    <message>
        <source>largest error from half a step per actuator</source>
        <translation>највећа грешка од пола корака сваког погона</translation>
    </message>
    <message>
        <source>stiffness K = Jᵀ·K_q·J (N/mm, N/rad, N·mm/rad)</source>
        <translation>крутост K = Jᵀ·K_q·J (N/mm, N/rad, N·mm/rad)</translation>
    </message>
    <message>
        <source>stiffness K = Jᵀ·K_q·J</source>
        <translation>крутост K = Jᵀ·K_q·J</translation>
    </message>
    <message>
        <source>stiffness in the weakest direction</source>
        <translation>крутост у најслабијем правцу</translation>
    </message>
    <message>
        <source>measured static stiffness of the whole joint (the document)</source>
        <translation>измерена статичка крутост целог зглоба (из документа)</translation>
    </message>
    <message>
        <source>N/mm</source>
        <translation>N/mm</translation>
    </message>
    <message>
        <source>axial stiffness of the actuator</source>
        <translation>аксијална крутост погона</translation>
    </message>
    <message>
        <source>measured static stiffness of the joint</source>
        <translation>измерена статичка крутост зглоба</translation>
    </message>
    <message>
        <source>load: torque on the output link</source>
        <translation>оптерећење: момент на излазном чланку</translation>
    </message>
    <message>
        <source>load: force on the platform, x</source>
        <translation>оптерећење: сила на платформи, x</translation>
    </message>
    <message>
        <source>load: force on the platform, y</source>
        <translation>оптерећење: сила на платформи, y</translation>
    </message>
    <message>
        <source>load: moment on the platform</source>
        <translation>оптерећење: момент на платформи</translation>
    </message>
    <message>
        <source>deflection under the load (actuators&apos; compliance)</source>
        <translation>угиб под оптерећењем (попустљивост актуатора)</translation>
    </message>
    <message>
        <source>deflection of the platform point under the load</source>
        <translation>померај тачке платформе под оптерећењем</translation>
    </message>
    <message>
        <source>length of the deflection under the load</source>
        <translation>величина помераја под оптерећењем</translation>
    </message>
    <message>
        <source>rotation of the platform under the load</source>
        <translation>заокрет платформе под оптерећењем</translation>
    </message>
    <message>
        <source>undefined at this singular pose</source>
        <translation>недефинисано у овом сингуларном положају</translation>
    </message>
    <message>
        <source>cut at the edge of the drawing</source>
        <translation>одсечено на ивици цртежа</translation>
    </message>
    <message>
        <source>velocity: 1 mm ≙ %1 mm/s</source>
        <translation>брзина: 1 mm ≙ %1 mm/s</translation>
    </message>
    <message>
        <source>unbounded: the locked actuators do not hold the platform (direct singularity)</source>
        <translation>неограничено: закочени актуатори не држе платформу (директна сингуларност)</translation>
    </message>
    <message>
        <source>force: 1 mm ≙ %1 N</source>
        <translation>сила: 1 mm ≙ %1 N</translation>
    </message>
    <message>
        <source>unbounded: a stretched leg holds any force along it (inverse singularity)</source>
        <translation>неограничено: испружена нога држи сваку силу дуж себе (инверзна сингуларност)</translation>
    </message>
    <message>
        <source>The design has no parameter named &apos;%1&apos; to give a tolerance.</source>
        <translation>Конструкција нема параметар „%1” коме би се задала толеранција.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; (%2) is not a geometric parameter: tolerances apply to the lengths, positions and angles of the design.</source>
        <translation>„%1” (%2) није геометријски параметар: толеранције се задају дужинама, положајима и угловима конструкције.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is derived from other parameters: give the tolerances of the parameters it is made of.</source>
        <translation>„%1” се изводи из других параметара: задајте толеранције параметара од којих настаје.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; has no say in this design, so a tolerance on it changes nothing.</source>
        <translation>„%1” не утиче на ову конструкцију, па толеранција на њему ништа не мења.</translation>
    </message>
    <message>
        <source>The tolerance of &apos;%1&apos; must be a finite number ≥ 0.</source>
        <translation>Толеранција за „%1” мора бити коначан број ≥ 0.</translation>
    </message>
    <message>
        <source>The tolerance ±%2 of &apos;%1&apos; takes it to %3, outside its allowed values.</source>
        <translation>Толеранција ±%2 за „%1” доводи га до %3, ван дозвољених вредности.</translation>
    </message>
    <message>
        <source>At most %1 tolerances can be given.</source>
        <translation>Може се задати највише %1 толеранција.</translation>
    </message>
    <message>
        <source>At a direct singularity the actuators do not hold the platform: the error from the tolerances is unbounded.</source>
        <translation>У сингуларитету директне кинематике актуатори не држе платформу: грешка од толеранција је неограничена.</translation>
    </message>
    <message>
        <source>At a combined singularity the error from the tolerances is undefined.</source>
        <translation>У комбинованом сингуларитету грешка од толеранција није дефинисана.</translation>
    </message>
    <message>
        <source>The perturbed designs do not assemble at these inputs: the error from the tolerances is undefined here.</source>
        <translation>Измењене конструкције се не склапају при овим улазима: грешка од толеранција овде није дефинисана.</translation>
    </message>
    <message>
        <source>The requirement &apos;%1&apos; cannot be checked: this design declares no actuators.</source>
        <translation>Захтев „%1“ не може да се провери: ова конструкција не задаје погоне.</translation>
    </message>
    <message>
        <source>The requirement &apos;%1&apos; has no comparison: write it as NAME&gt;=VALUE or NAME&lt;=VALUE, for example force_worst&gt;=50.</source>
        <translation>Захтев „%1“ нема поређење: напишите га као ИМЕ&gt;=ВРЕДНОСТ или ИМЕ&lt;=ВРЕДНОСТ, на пример force_worst&gt;=50.</translation>
    </message>
    <message>
        <source>The requirement &apos;%1&apos; names no single capability value; it may name %2.</source>
        <translation>Захтев „%1“ не именује ниједну појединачну вредност могућности погона; може да именује %2.</translation>
    </message>
    <message>
        <source>The requirement &apos;%1&apos; does not end in a finite number.</source>
        <translation>Захтев „%1“ се не завршава коначним бројем.</translation>
    </message>
    <message>
        <source>worst-case error from the tolerances</source>
        <translation>највећа грешка од толеранција</translation>
    </message>
    <message>
        <source>near an inverse singularity: an actuator moves the platform less than 1/1000 of what it does at the home pose</source>
        <translation>близу сингуларитета инверзне кинематике: погон помера платформу мање од 1/1000 онога што чини у почетном положају</translation>
    </message>
    <message>
        <source>near a direct singularity: an actuator moves the platform more than 1000 times what it does at the home pose</source>
        <translation>близу сингуларитета директне кинематике: погон помера платформу више од 1000 пута више него у почетном положају</translation>
    </message>
    <message>
        <source>near a combined singularity: one actuator moves the platform less than 1/1000, another more than 1000 times what it does at the home pose</source>
        <translation>близу комбинованог сингуларитета: један погон помера платформу мање од 1/1000, други више од 1000 пута више него у почетном положају</translation>
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
        <translation>C не може да стигне до тачке %1 у овом начину склапања (%2): прешла би праву BD, на којој су спојке на истој правој (сингуларитет директне кинематике); пређите на други начин склапања да бисте наставили.</translation>
    </message>
    <message>
        <source>The numbers put in are rounded as shown; every result is worked out from the unrounded values, so the last digits of a result can differ from one worked out by hand from the shown numbers.</source>
        <translation>Уврштени бројеви су заокружени као што су приказани; сваки резултат је израчунат из незаокружених вредности, па се последње цифре резултата могу разликовати од оних које се добију ручно из приказаних бројева.</translation>
    </message>
    <message>
        <source>constant orientation</source>
        <translation>стална оријентација</translation>
    </message>
    <message>
        <source>free body</source>
        <translation>слободно тело</translation>
    </message>
    <message>
        <source>°/s</source>
        <translation>°/s</translation>
    </message>
    <message>
        <source>platform: 2 DOF as a point or with constant orientation, 3 as a free body</source>
        <translation>платформа: 2 степена слободе као тачка или са сталном оријентацијом, 3 као слободно тело</translation>
    </message>
    <message>
        <source>leg 1: type (the actuated joint underlined)</source>
        <translation>нога 1: тип (погонски зглоб подвучен)</translation>
    </message>
    <message>
        <source>leg 2: type (the actuated joint underlined)</source>
        <translation>нога 2: тип (погонски зглоб подвучен)</translation>
    </message>
    <message>
        <source>leg 3: type (the actuated joint underlined)</source>
        <translation>нога 3: тип (погонски зглоб подвучен)</translation>
    </message>
    <message>
        <source>At these inputs the platform would have left its assembly mode: it ends on the way, where it meets another at a direct singularity. Switch the assembly mode to go on.</source>
        <translation>При овим улазима платформа би напустила свој начин склапања: он се завршава на путу, где се среће са другим у сингуларитету директне кинематике. Да бисте наставили, промените начин склапања.</translation>
    </message>
    <message>
        <source>leg 1: working mode, the elbow left or right of A₁→P₁ (P̲RR: left, the root q = B + √…)</source>
        <translation>нога 1: радни режим, лакат лево или десно од A₁→P₁ (P̲RR: лево — корен q = B + √…)</translation>
    </message>
    <message>
        <source>leg 2: working mode, the elbow left or right of A₂→P₂ (P̲RR: left, the root q = B + √…)</source>
        <translation>нога 2: радни режим, лакат лево или десно од A₂→P₂ (P̲RR: лево — корен q = B + √…)</translation>
    </message>
    <message>
        <source>leg 3: working mode, the elbow left or right of A₃→P₃ (P̲RR: left, the root q = B + √…)</source>
        <translation>нога 3: радни режим, лакат лево или десно од A₃→P₃ (P̲RR: лево — корен q = B + √…)</translation>
    </message>
    <message>
        <source>Jacobian, its own determinant (one input, one output)</source>
        <translation>Јакобијан, уједно своја детерминанта (један улаз, један излаз)</translation>
    </message>
    <message>
        <source>J maps the rocker&apos;s rate onto the crank&apos;s, α̇ = J·δ̇, so J = 1/i₃₁.</source>
        <translation>J пресликава брзину клацкалице у брзину полуге, α̇ = J·δ̇, па је J = 1/i₃₁.</translation>
    </message>
    <message>
        <source>behind</source>
        <translation>иза</translation>
    </message>
    <message>
        <source>ahead</source>
        <translation>испред</translation>
    </message>
    <message>
        <source>working mode of leg 1: the platform behind slider Z₁ along guide 1 or ahead of it</source>
        <translation>радни режим ноге 1: платформа иза клизача Z₁ дуж вођице 1 или испред њега</translation>
    </message>
    <message>
        <source>working mode of leg 2: the platform behind slider Z₂ along guide 2 or ahead of it</source>
        <translation>радни режим ноге 2: платформа иза клизача Z₂ дуж вођице 2 или испред њега</translation>
    </message>
    <message>
        <source>assembly mode: the platform left or right of Z₁→Z₂</source>
        <translation>начин склапања: платформа лево или десно од Z₁→Z₂</translation>
    </message>
    <message>
        <source>u₁ = x − s/2 − x_AB and u₂ = x + s/2 − x_CD are the rods&apos; runs along the guides, w and −w in the O form, −w and w in the X form.</source>
        <translation>u₁ = x − s/2 − x_AB и u₂ = x + s/2 − x_CD су пројекције шипки дуж вођица: w и −w у облику O, −w и w у облику X.</translation>
    </message>
    <message>
        <source>Jacobian J = ∂d/∂θ</source>
        <translation>Јакобијан J = ∂d/∂θ</translation>
    </message>
    <message>
        <source>Output speed at the diagonal&apos;s top speed</source>
        <translation>Излазна брзина при највећој брзини дијагонале</translation>
    </message>
    <message>
        <source>Derivative of J, for the diagonal&apos;s acceleration</source>
        <translation>Извод J, за убрзање дијагонале</translation>
    </message>
    <message>
        <source>J_i is the П-joint&apos;s Jacobian ∂d/∂θ of a П̲RR leg and 1 for the other leg types; C_i is A_i for an RP̲R leg.</source>
        <translation>J_i је јакобијан П-зглоба ∂d/∂θ за ногу П̲RR и 1 за ноге других типова; C_i је A_i за ногу RP̲R.</translation>
    </message>
    <message>
        <source>C_i is the centre of leg i&apos;s circle: the elbow, the slider joint, or A_i for an RP̲R leg.</source>
        <translation>C_i је средиште кружнице ноге i: лакат, зглоб клизача или A_i за ногу RP̲R.</translation>
    </message>
</context>
<context>
    <name>pkm::Animation</name>
    <message>
        <source>The animation needs a pose variable of the mechanism.</source>
        <translation>За анимацију је потребна променљива положаја механизма.</translation>
    </message>
    <message>
        <source>An animation has %1 to %2 frames, not %3.</source>
        <translation>Анимација мора имати од %1 до %2 кадрова, а не %3.</translation>
    </message>
    <message>
        <source>Frame %1 (%2 = %3): %4</source>
        <translation>Кадар %1 (%2 = %3): %4</translation>
    </message>
    <message>
        <source>The animation was cancelled.</source>
        <translation>Анимација је отказана.</translation>
    </message>
    <message>
        <source>A video file&apos;s name ends in .mp4 or .webm: %1.</source>
        <translation>Име видео-датотеке се завршава на .mp4 или .webm: %1.</translation>
    </message>
    <message>
        <source>An animation draws at most %1 million pixels (frames × width × height); %2 frames of %3 × %4 would be %5 million: take fewer steps or a smaller size.</source>
        <translation>Анимација црта највише %1 милиона пиксела (кадрови × ширина × висина); %2 кадрова величине %3 × %4 било би %5 милиона: узмите мање корака или мању величину.</translation>
    </message>
</context>
<context>
    <name>pkm::AnimationDialog</name>
    <message>
        <source>Beside the view</source>
        <translation>Поред приказа</translation>
    </message>
    <message>
        <source>Each frame shows the mechanism at the left and this plot at the right, its cursor following the pose.</source>
        <translation>Сваки кадар приказује механизам лево и овај дијаграм десно; курсор дијаграма прати положај.</translation>
    </message>
    <message>
        <source>Nothing</source>
        <translation>Ништа</translation>
    </message>
    <message>
        <source>The plot on screen: %1</source>
        <translation>Дијаграм на екрану: %1</translation>
    </message>
    <message>
        <source>%1 against %2 — %3</source>
        <translation>%1 од %2 — %3</translation>
    </message>
    <message>
        <source>Export Animation</source>
        <translation>Извоз анимације</translation>
    </message>
    <message>
        <source>Move</source>
        <translation>Променљива</translation>
    </message>
    <message>
        <source>From</source>
        <translation>Од</translation>
    </message>
    <message>
        <source>To</source>
        <translation>До</translation>
    </message>
    <message>
        <source>Frames</source>
        <translation>Број кадрова</translation>
    </message>
    <message>
        <source> ms per frame</source>
        <translation> ms по кадру</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Брзина</translation>
    </message>
    <message>
        <source>%1 × %2 pixels</source>
        <translation>%1 × %2 пиксела</translation>
    </message>
    <message>
        <source>Size</source>
        <translation>Величина</translation>
    </message>
    <message>
        <source>Play back to the start (a smooth loop)</source>
        <translation>Враћање на почетак (глатка петља)</translation>
    </message>
    <message>
        <source>Export…</source>
        <translation>Извези…</translation>
    </message>
    <message numerus="yes">
        <source>Drawing %n frame(s)…</source>
        <translation>
            <numerusform>Цртање %n кадра…</numerusform>
            <numerusform>Цртање %n кадра…</numerusform>
            <numerusform>Цртање %n кадрова…</numerusform>
        </translation>
    </message>
    <message>
        <source>Cannot write %1: %2.</source>
        <translation>Није могуће уписати %1: %2.</translation>
    </message>
    <message>
        <source>Animation export cancelled.</source>
        <translation>Извоз анимације је отказан.</translation>
    </message>
    <message>
        <source>Wrote %1 (%2 kB)</source>
        <translation>Уписано %1 (%2 kB)</translation>
    </message>
    <message>
        <source>Animated GIF</source>
        <translation>Анимирани GIF</translation>
    </message>
    <message>
        <source>MP4 video (H.264, 30 frames/s)</source>
        <translation>MP4 видео (H.264, 30 кадрова/s)</translation>
    </message>
    <message>
        <source>WebM video (VP9, 30 frames/s)</source>
        <translation>WebM видео (VP9, 30 кадрова/s)</translation>
    </message>
    <message>
        <source>Format</source>
        <translation>Формат</translation>
    </message>
    <message>
        <source>A GIF&apos;s speed; a video plays 30 frames per second.</source>
        <translation>Брзина GIF-а; видео се пушта са 30 кадрова у секунди.</translation>
    </message>
    <message>
        <source>Animated GIF (*.gif)</source>
        <translation>Анимирани GIF (*.gif)</translation>
    </message>
    <message>
        <source>MP4 video (*.mp4)</source>
        <translation>MP4 видео (*.mp4)</translation>
    </message>
    <message>
        <source>WebM video (*.webm)</source>
        <translation>WebM видео (*.webm)</translation>
    </message>
    <message numerus="yes">
        <source>Encoding %n frame(s)…</source>
        <translation>
            <numerusform>Кодирање %n кадра…</numerusform>
            <numerusform>Кодирање %n кадра…</numerusform>
            <numerusform>Кодирање %n кадрова…</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>pkm::AnimationPlot</name>
    <message>
        <source>%1 against %2</source>
        <translation>%1 (на апсциси: %2)</translation>
    </message>
    <message>
        <source>— (undefined at this singular pose)</source>
        <translation>— (није дефинисано у овом сингуларном положају)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a quantity the %2 can plot; it has %3</source>
        <translation>„%1” није величина коју %2 може да прикаже; постоје: %3</translation>
    </message>
</context>
<context>
    <name>pkm::BackgroundTask</name>
    <message>
        <source>Cancel</source>
        <translation>Откажи</translation>
    </message>
</context>
<context>
    <name>pkm::DesignPanel</name>
    <message>
        <source>Geometry</source>
        <translation>Геометрија</translation>
    </message>
    <message>
        <source>Motion range</source>
        <translation>Опсег кретања</translation>
    </message>
    <message>
        <source>Actuator</source>
        <translation>Актуатор</translation>
    </message>
    <message>
        <source>Motor body (drawing)</source>
        <translation>Кућиште мотора (цртеж)</translation>
    </message>
    <message>
        <source>Modes</source>
        <translation>Режими</translation>
    </message>
    <message>
        <source>less</source>
        <translation>мање</translation>
    </message>
    <message>
        <source>more…</source>
        <translation>више…</translation>
    </message>
    <message>
        <source>greater than %1</source>
        <translation>веће од %1</translation>
    </message>
    <message>
        <source>between %1 and %2</source>
        <translation>између %1 и %2</translation>
    </message>
    <message>
        <source>The last valid design is kept.</source>
        <translation>Задржава се последња исправна конструкција.</translation>
    </message>
    <message>
        <source>%1 (%2): &apos;%3&apos; is not a number.</source>
        <translation>%1 (%2): „%3“ није број.</translation>
    </message>
    <message>
        <source>%1: %2. Up/Down or the mouse wheel step by %3.</source>
        <translation>%1: %2. Тастери ↑/↓ или точкић миша мењају вредност у корацима од %3.</translation>
    </message>
    <message>
        <source>Name in design files and on the command line: %1</source>
        <translation>Име у датотекама конструкција и у командној линији: %1</translation>
    </message>
</context>
<context>
    <name>pkm::DesignSession</name>
    <message>
        <source>Untitled design</source>
        <translation>Конструкција без назива</translation>
    </message>
    <message>
        <source>Cannot write %1: %2.</source>
        <translation>Није могуће уписати %1: %2.</translation>
    </message>
</context>
<context>
    <name>pkm::Document</name>
    <message>
        <source>Open %1</source>
        <translation>Отвори %1</translation>
    </message>
    <message>
        <source>Switch to %1</source>
        <translation>Прелаз: %1</translation>
    </message>
    <message>
        <source>%1 stops at its upper limit %2: %3.</source>
        <translation>%1 се зауставља на горњој граници %2: %3.</translation>
    </message>
    <message>
        <source>%1 stops at its lower limit %2: %3.</source>
        <translation>%1 се зауставља на доњој граници %2: %3.</translation>
    </message>
    <message>
        <source>%1 stops at its upper limit %2 (design range).</source>
        <translation>%1 се зауставља на горњој граници %2 (пројектовани опсег).</translation>
    </message>
    <message>
        <source>%1 stops at its lower limit %2 (design range).</source>
        <translation>%1 се зауставља на доњој граници %2 (пројектовани опсег).</translation>
    </message>
    <message>
        <source>Close to a singular pose: small input steps make large output jumps.</source>
        <translation>Близу сингуларног положаја: мали кораци на улазу дају велике скокове на излазу.</translation>
    </message>
    <message>
        <source>That mode is not available at this pose.</source>
        <translation>Тај режим није доступан у овом положају.</translation>
    </message>
    <message>
        <source>Singular pose (inverse): the mechanism cannot be driven here.</source>
        <translation>Сингуларан положај (инверзне кинематике): механизмом се овде не може управљати.</translation>
    </message>
    <message>
        <source>Singular pose (direct): the mechanism cannot be driven here.</source>
        <translation>Сингуларан положај (директне кинематике): механизмом се овде не може управљати.</translation>
    </message>
    <message>
        <source>Singular pose (combined): the mechanism cannot be driven here.</source>
        <translation>Сингуларан положај (комбиновани): механизмом се овде не може управљати.</translation>
    </message>
    <message>
        <source>A design keeps at most %1 bookmarks: remove one first.</source>
        <translation>Конструкција чува највише %1 обележивача: прво уклоните један.</translation>
    </message>
    <message>
        <source>Add bookmark “%1”</source>
        <translation>Додај обележивач „%1”</translation>
    </message>
    <message>
        <source>There is no bookmark %1.</source>
        <translation>Нема обележивача %1.</translation>
    </message>
    <message>
        <source>Remove bookmark “%1”</source>
        <translation>Уклони обележивач „%1”</translation>
    </message>
    <message>
        <source>Bookmark “%1”: %2</source>
        <translation>Обележивач „%1”: %2</translation>
    </message>
    <message>
        <source>New design from template %1</source>
        <translation>Нова конструкција из шаблона %1</translation>
    </message>
    <message>
        <source>Move %1</source>
        <translation>Помери %1</translation>
    </message>
    <message>
        <source>A design keeps at most %1 tolerances.</source>
        <translation>Конструкција чува највише %1 толеранција.</translation>
    </message>
    <message>
        <source>Change tolerance of %1</source>
        <translation>Измени толеранцију за %1</translation>
    </message>
    <message>
        <source>Clear tolerances</source>
        <translation>Уклони толеранције</translation>
    </message>
    <message>
        <source>Change requirements</source>
        <translation>Измени захтеве</translation>
    </message>
</context>
<context>
    <name>pkm::EquationsPanel</name>
    <message>
        <source>This kind lists no equations.</source>
        <translation>За ову врсту механизма једначине нису наведене.</translation>
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
        <translation>унија (контура): %1</translation>
    </message>
    <message>
        <source>Areas of the forms: exact (closed form). Union: counted on a %1 × %2 grid.</source>
        <translation>Површине облика: тачне (по формулама). Унија: пребројана на мрежи %1 × %2.</translation>
    </message>
    <message>
        <source>Areas counted on a %1 × %2 grid.</source>
        <translation>Површине пребројане на мрежи %1 × %2.</translation>
    </message>
</context>
<context>
    <name>pkm::FourBarPanel</name>
    <message>
        <source>Link lengths</source>
        <translation>Дужине чланова</translation>
    </message>
    <message>
        <source>AB crank</source>
        <translation>AB полуга</translation>
    </message>
    <message>
        <source>BC coupler</source>
        <translation>BC спојка</translation>
    </message>
    <message>
        <source>CD rocker</source>
        <translation>CD клацкалица</translation>
    </message>
    <message>
        <source>AD ground</source>
        <translation>AD постоље</translation>
    </message>
    <message>
        <source>Transmission angle γ at C</source>
        <translation>Угао преноса γ у C</translation>
    </message>
    <message>
        <source>The crank drives the rocker well when γ stays between %1° and %2°.</source>
        <translation>Полуга добро покреће клацкалицу док је γ између %1° и %2°.</translation>
    </message>
    <message>
        <source>The last valid design is kept.</source>
        <translation>Задржава се последња исправна конструкција.</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>the crank AB, the shortest link, turns fully; the rocker CD swings.</source>
        <translation>полуга AB, најкраћи члан, окреће се пуним кругом; клацкалица CD осцилује.</translation>
    </message>
    <message>
        <source>the rocker CD, the shortest link, could turn fully; the crank AB only swings.</source>
        <translation>клацкалица CD, најкраћи члан, могла би да се окреће пуним кругом; полуга AB само осцилује.</translation>
    </message>
    <message>
        <source>the ground AD is the shortest link: the crank and the rocker both turn fully (drag link).</source>
        <translation>постоље AD је најкраћи члан: и полуга и клацкалица окрећу се пуним кругом (двострука полуга).</translation>
    </message>
    <message>
        <source>the coupler BC is the shortest link: the crank and the rocker only swing.</source>
        <translation>спојка BC је најкраћи члан: полуга и клацкалица само осцилују.</translation>
    </message>
    <message>
        <source>non-Grashof: no link turns fully.</source>
        <translation>Грасхофов услов није испуњен: ниједан члан се не окреће пуним кругом.</translation>
    </message>
    <message>
        <source>the links can fold flat in line, where the open and crossed branches meet.</source>
        <translation>чланови могу да се сложе у једну линију, где се сусрећу отворена и укрштена грана.</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;: s + l = %2 %3 p + q = %4; %5</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;: s + l = %2 %3 p + q = %4; %5</translation>
    </message>
    <message>
        <source>&lt;b&gt;α&lt;/b&gt;: the crank turns fully, %1 … %2</source>
        <translation>&lt;b&gt;α&lt;/b&gt;: полуга се окреће пуним кругом, %1 … %2</translation>
    </message>
    <message>
        <source>&lt;b&gt;α&lt;/b&gt; assembles from %1 to %2 only: at the ends the coupler and the rocker are in line (dead points)</source>
        <translation>&lt;b&gt;α&lt;/b&gt;: механизам се може склопити само од %1 до %2; на крајевима су спојка и клацкалица у истој линији (мртве тачке)</translation>
    </message>
    <message>
        <source>&lt;span style=&apos;color:#b3261e&apos;&gt;over the motion %1° … %2°: enters the poor band&lt;/span&gt;</source>
        <translation>&lt;span style=&apos;color:#b3261e&apos;&gt;током кретања %1° … %2°: улази у зону лошег преноса&lt;/span&gt;</translation>
    </message>
    <message>
        <source>over the motion %1° … %2°: inside %3° … %4°</source>
        <translation>током кретања %1° … %2°: унутар %3° … %4°</translation>
    </message>
    <message>
        <source>%1 — poor: %2</source>
        <translation>%1 — лош пренос: %2</translation>
    </message>
    <message>
        <source>below %1°</source>
        <translation>испод %1°</translation>
    </message>
    <message>
        <source>above %1°</source>
        <translation>изнад %1°</translation>
    </message>
    <message>
        <source>α stops at its upper limit: %1.</source>
        <translation>α се зауставља на горњој граници: %1.</translation>
    </message>
    <message>
        <source>α stops at its lower limit: %1.</source>
        <translation>α се зауставља на доњој граници: %1.</translation>
    </message>
    <message>
        <source>Crank-rocker</source>
        <translation>Механизам полуга–клацкалица</translation>
    </message>
    <message>
        <source>Rocker-crank</source>
        <translation>Механизам клацкалица–полуга</translation>
    </message>
    <message>
        <source>Double-crank</source>
        <translation>Двострука полуга</translation>
    </message>
    <message>
        <source>Double-rocker</source>
        <translation>Двострука клацкалица</translation>
    </message>
    <message>
        <source>Triple-rocker</source>
        <translation>Трострука клацкалица</translation>
    </message>
    <message>
        <source>Change-point</source>
        <translation>Гранични Грасхофов случај</translation>
    </message>
    <message>
        <source>%1. &lt;b&gt;δ&lt;/b&gt; swings over %2 … %3 (crossed branch).</source>
        <translation>%1. &lt;b&gt;δ&lt;/b&gt; се мења у опсегу %2 … %3 (укрштена грана).</translation>
    </message>
    <message>
        <source>%1. &lt;b&gt;δ&lt;/b&gt; swings over %2 … %3 (open branch).</source>
        <translation>%1. &lt;b&gt;δ&lt;/b&gt; се мења у опсегу %2 … %3 (отворена грана).</translation>
    </message>
</context>
<context>
    <name>pkm::FourBarPlots</name>
    <message>
        <source>δ(α) — fig. 4</source>
        <translation>δ(α) — сл. 4</translation>
    </message>
    <message>
        <source>ω₃, ε₃ — fig. 6</source>
        <translation>ω₃, ε₃ — сл. 6</translation>
    </message>
    <message>
        <source>δ vs AB — fig. 5</source>
        <translation>δ од AB — сл. 5</translation>
    </message>
    <message>
        <source>The rocker angle δ over the crank&apos;s range (click to set α)</source>
        <translation>Угао клацкалице δ у целом опсегу полуге (кликом се задаје α)</translation>
    </message>
    <message>
        <source>The rocker&apos;s angular velocity and acceleration at constant ω₁ (click to set α)</source>
        <translation>Угаона брзина и угаоно убрзање клацкалице при сталној ω₁ (кликом се задаје α)</translation>
    </message>
    <message>
        <source>The transmission angle at C; shaded where the crank drives the rocker poorly</source>
        <translation>Угао преноса у зглобу C; осенчено је тамо где полуга лоше покреће клацкалицу</translation>
    </message>
    <message>
        <source>δ at the current α as the crank length AB changes, the other links fixed</source>
        <translation>δ при тренутном α у зависности од дужине полуге AB, остали чланови непромењени</translation>
    </message>
    <message>
        <source>Click or drag to set the crank angle α</source>
        <translation>Кликните или превуците да задате угао полуге α</translation>
    </message>
    <message>
        <source>AB/BC/CD/AD = %1/%2/%3/%4 mm, %5 branch</source>
        <translation>AB/BC/CD/AD = %1/%2/%3/%4 mm, %5 грана</translation>
    </message>
    <message>
        <source>Fig. 4 — rocker angle δ(α)</source>
        <translation>Сл. 4 — угао клацкалице δ(α)</translation>
    </message>
    <message>
        <source>Fig. 6 — rocker angular velocity ω₃ = dδ/dt</source>
        <translation>Сл. 6 — угаона брзина клацкалице ω₃ = dδ/dt</translation>
    </message>
    <message>
        <source>Fig. 6 — rocker angular acceleration ε₃ = d²δ/dt²</source>
        <translation>Сл. 6 — угаоно убрзање клацкалице ε₃ = d²δ/dt²</translation>
    </message>
    <message>
        <source>Transmission angle γ(α), (5)</source>
        <translation>Угао преноса γ(α), (5)</translation>
    </message>
    <message>
        <source>Fig. 5 — rocker angle δ against the crank length AB</source>
        <translation>Сл. 5 — угао клацкалице δ у зависности од дужине полуге AB</translation>
    </message>
    <message>
        <source>ω₁ = %1 rad/s constant; exact (the document&apos;s (8) has the opposite sign)</source>
        <translation>ω₁ = %1 rad/s = const; тачно (формула (8) из рада има супротан знак)</translation>
    </message>
    <message>
        <source>ω₁ = %1 rad/s constant; exact (not the document&apos;s (14))</source>
        <translation>ω₁ = %1 rad/s = const; тачно (не по формули (14) из рада)</translation>
    </message>
    <message>
        <source>at α = %1°; BC, CD, AD fixed</source>
        <translation>при α = %1°; BC, CD, AD непромењени</translation>
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
        <translation>дужина полуге AB (mm)</translation>
    </message>
    <message>
        <source>crank angle α (°)</source>
        <translation>угао полуге α (°)</translation>
    </message>
    <message>
        <source>poor transmission: |γ| &lt; %1° or &gt; %2°</source>
        <translation>лош пренос: |γ| &lt; %1° или &gt; %2°</translation>
    </message>
    <message>
        <source>δ at α = %1°</source>
        <translation>δ при α = %1°</translation>
    </message>
    <message>
        <source>largest AB that assembles: %1 mm</source>
        <translation>највећа AB која се може склопити: %1 mm</translation>
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
        <translation>%1 → %2∞: мртва тачка</translation>
    </message>
    <message>
        <source>no pose</source>
        <translation>нема положаја</translation>
    </message>
    <message>
        <source>crossed</source>
        <comment>branch</comment>
        <translation>укрштена</translation>
    </message>
    <message>
        <source>open</source>
        <comment>branch</comment>
        <translation>отворена</translation>
    </message>
</context>
<context>
    <name>pkm::GifWriter</name>
    <message>
        <source>An animation needs at least one frame.</source>
        <translation>Анимацији је потребан бар један кадар.</translation>
    </message>
    <message>
        <source>A GIF frame must be 1 to 65535 pixels on each side.</source>
        <translation>GIF кадар мора имати од 1 до 65535 пиксела по свакој страници.</translation>
    </message>
    <message>
        <source>All frames of a GIF must have the same size.</source>
        <translation>Сви кадрови GIF-а морају бити исте величине.</translation>
    </message>
    <message>
        <source>giflib: out of memory.</source>
        <translation>giflib: нема довољно меморије.</translation>
    </message>
    <message>
        <source>giflib could not reduce a frame to 256 colours.</source>
        <translation>giflib није успео да сведе кадар на 256 боја.</translation>
    </message>
</context>
<context>
    <name>pkm::GuideWindow</name>
    <message>
        <source>PKM Studio User Guide</source>
        <translation>Упутство за PKM Studio</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Назад</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>На почетак</translation>
    </message>
    <message>
        <source>The start of the guide</source>
        <translation>Почетак упутства</translation>
    </message>
    <message>
        <source>&amp;Find:</source>
        <translation>&amp;Пронађи:</translation>
    </message>
    <message>
        <source>a word in the guide (Ctrl+F)</source>
        <translation>реч у упутству (Ctrl+F)</translation>
    </message>
    <message>
        <source>Previous</source>
        <translation>Претходно</translation>
    </message>
    <message>
        <source>Next</source>
        <translation>Следеће</translation>
    </message>
    <message>
        <source>Not found</source>
        <translation>Није пронађено</translation>
    </message>
</context>
<context>
    <name>pkm::LinkageView</name>
    <message>
        <source>Click to switch to: %1</source>
        <translation>Кликните да пребаците: %1</translation>
    </message>
    <message>
        <source>this pose</source>
        <translation>овај положај</translation>
    </message>
</context>
<context>
    <name>pkm::LinkageView3D</name>
    <message>
        <source>3D view unavailable: OpenGL 3.3 could not be started.</source>
        <translation>3D приказ није доступан: OpenGL 3.3 није могао да се покрене.</translation>
    </message>
    <message>
        <source>A picture needs a size of at least one pixel.</source>
        <translation>Слика мора бити велика бар један пиксел.</translation>
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
        <translation>Механизам у 3D: превуците да га окренете, десним тастером да га померите, точкићем за увећање</translation>
    </message>
    <message>
        <source>Design</source>
        <translation>Конструкција</translation>
    </message>
    <message>
        <source>Mobility</source>
        <translation>Покретљивост</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Датотека</translation>
    </message>
    <message>
        <source>&amp;Open Design…</source>
        <translation>&amp;Отвори конструкцију…</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>Отвори &amp;скорашње</translation>
    </message>
    <message>
        <source>&amp;Save Design</source>
        <translation>&amp;Сачувај конструкцију</translation>
    </message>
    <message>
        <source>Save Design &amp;As…</source>
        <translation>Сачувај конструкцију &amp;као…</translation>
    </message>
    <message>
        <source>Export &amp;Drawing (DXF)…</source>
        <translation>Извези &amp;цртеж (DXF)…</translation>
    </message>
    <message>
        <source>Export &amp;Parameter Sheet…</source>
        <translation>Извези &amp;листу параметара…</translation>
    </message>
    <message>
        <source>Save 2D &amp;View Picture…</source>
        <translation>Сачувај слику &amp;2D приказа…</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Излаз</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Уређивање</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Опозови</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Понови</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Опозови</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Понови</translation>
    </message>
    <message>
        <source>&amp;Presets</source>
        <translation>&amp;Примери</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Приказ</translation>
    </message>
    <message>
        <source>&amp;Fit Mechanism</source>
        <translation>&amp;Уклопи механизам</translation>
    </message>
    <message>
        <source>Zoom &amp;In</source>
        <translation>&amp;Увећај</translation>
    </message>
    <message>
        <source>Zoom &amp;Out</source>
        <translation>&amp;Умањи</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Помоћ</translation>
    </message>
    <message>
        <source>&amp;About PKM Studio</source>
        <translation>&amp;О програму PKM Studio</translation>
    </message>
    <message>
        <source>Switched to %1.</source>
        <translation>Прелазак на: %1.</translation>
    </message>
    <message>
        <source>Open Design</source>
        <translation>Отварање конструкције</translation>
    </message>
    <message>
        <source>PKM Studio designs (*.pkm.json);;All files (*)</source>
        <translation>Конструкције PKM Studio (*.pkm.json);;Све датотеке (*)</translation>
    </message>
    <message>
        <source>Save Design</source>
        <translation>Чување конструкције</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>Сачувано: %1</translation>
    </message>
    <message>
        <source>Save Design As</source>
        <translation>Чување конструкције као</translation>
    </message>
    <message>
        <source>PKM Studio designs (*.pkm.json)</source>
        <translation>Конструкције PKM Studio (*.pkm.json)</translation>
    </message>
    <message>
        <source>Unsaved Changes</source>
        <translation>Несачуване измене</translation>
    </message>
    <message>
        <source>The design “%1” has changes that are not saved. Save them?</source>
        <translation>Конструкција „%1“ има несачуване измене. Да ли да их сачувам?</translation>
    </message>
    <message>
        <source>Recover Design</source>
        <translation>Враћање конструкције</translation>
    </message>
    <message>
        <source>PKM Studio closed unexpectedly while “%1” had unsaved changes (autosaved %2). Recover them?</source>
        <translation>PKM Studio се неочекивано затворио док је „%1“ имала несачуване измене (аутоматски сачувано %2). Да ли да их вратим?</translation>
    </message>
    <message>
        <source>Recovered “%1”: save it to keep the changes.</source>
        <translation>Враћено „%1“: сачувајте да бисте задржали измене.</translation>
    </message>
    <message>
        <source>%1[*] — PKM Studio</source>
        <translation>%1[*] — PKM Studio</translation>
    </message>
    <message>
        <source>%1 no longer exists; removed from the recent files.</source>
        <translation>%1 више не постоји; уклоњена је са списка скорашњих датотека.</translation>
    </message>
    <message>
        <source>About PKM Studio</source>
        <translation>О програму PKM Studio</translation>
    </message>
    <message>
        <source>&lt;h3&gt;PKM Studio %1&lt;/h3&gt;&lt;p&gt;Design, analysis and teaching of parallel-kinematic mechanisms.&lt;/p&gt;&lt;p&gt;Licensed under the GNU General Public License, version 3 or later.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;PKM Studio %1&lt;/h3&gt;&lt;p&gt;Пројектовање, анализа и настава механизама паралелне кинематике.&lt;/p&gt;&lt;p&gt;Лиценца: GNU General Public License, верзија 3 или новија.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Export Drawing (DXF)</source>
        <translation>Извоз цртежа (DXF)</translation>
    </message>
    <message>
        <source>DXF drawings (*.dxf);;All files (*)</source>
        <translation>DXF цртежи (*.dxf);;Све датотеке (*)</translation>
    </message>
    <message>
        <source>Cannot write the drawing to %1: %2.</source>
        <translation>Цртеж није могуће уписати у %1: %2.</translation>
    </message>
    <message>
        <source>Wrote the drawing to %1 (DXF R12, mm).</source>
        <translation>Цртеж је уписан у %1 (DXF R12, mm).</translation>
    </message>
    <message>
        <source>Export Parameter Sheet</source>
        <translation>Извоз листе параметара</translation>
    </message>
    <message>
        <source>PDF parameter sheets (*.pdf);;JSON (*.json);;CSV (*.csv)</source>
        <translation>Листе параметара PDF (*.pdf);;JSON (*.json);;CSV (*.csv)</translation>
    </message>
    <message>
        <source>Computing the parameter sheet…</source>
        <translation>Рачунам листу параметара…</translation>
    </message>
    <message>
        <source>Wrote the parameter sheet to %1.</source>
        <translation>Листа параметара је уписана у %1.</translation>
    </message>
    <message>
        <source>Wrote the 2D view to %1.</source>
        <translation>2D приказ је уписан у %1.</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Језик</translation>
    </message>
    <message>
        <source>Main Toolbar</source>
        <translation>Главна трака алата</translation>
    </message>
    <message>
        <source>The language “%1” is not available.</source>
        <translation>Језик „%1“ није доступан.</translation>
    </message>
    <message>
        <source>&amp;Source Documents…</source>
        <translation>&amp;Изворни документи…</translation>
    </message>
    <message>
        <source>Source Documents</source>
        <translation>Изворни документи</translation>
    </message>
    <message>
        <source>&lt;p&gt;PKM Studio models the mechanisms of these four documents: the active П-joint (1), MOMA (2), the O-X glide (3), the four-bar and the mobility formulas (4). Where a printed formula or number is wrong, the program uses the corrected one; the README&apos;s section on the mathematics lists each correction.&lt;/p&gt;%1</source>
        <translation>&lt;p&gt;PKM Studio моделира механизме ова четири документа: активни П-зглоб (1), MOMA (2), O-X glide (3), зглобни четвороугао и формуле покретљивости (4). Где је штампана формула или број погрешан, програм користи исправљени; одељак README-а о математици наводи свако исправљање.&lt;/p&gt;%1</translation>
    </message>
    <message>
        <source>Play Toolbar</source>
        <translation>Трака за покретање</translation>
    </message>
    <message>
        <source>Play / &amp;Pause</source>
        <translation>Покрени / &amp;пауза</translation>
    </message>
    <message>
        <source>Move the chosen joint variable by itself, or stop it</source>
        <translation>Покреће изабрану променљиву зглоба саму од себе или је зауставља</translation>
    </message>
    <message>
        <source>&amp;Bookmarks</source>
        <translation>&amp;Обележивачи</translation>
    </message>
    <message>
        <source>&amp;Add Bookmark</source>
        <translation>&amp;Додај обележивач</translation>
    </message>
    <message>
        <source>Keep this pose to come back to it (saved with the design)</source>
        <translation>Запамти овај положај да му се вратиш (чува се уз конструкцију)</translation>
    </message>
    <message>
        <source>&amp;Previous Bookmark</source>
        <translation>&amp;Претходни обележивач</translation>
    </message>
    <message>
        <source>&amp;Next Bookmark</source>
        <translation>&amp;Следећи обележивач</translation>
    </message>
    <message>
        <source>&amp;Remove Current Bookmark</source>
        <translation>&amp;Уклони тренутни обележивач</translation>
    </message>
    <message>
        <source>Bookmark %1 kept: %2</source>
        <translation>Обележивач %1 запамћен: %2</translation>
    </message>
    <message>
        <source>Bookmark %1 of %2: %3</source>
        <translation>Обележивач %1 од %2: %3</translation>
    </message>
    <message>
        <source>No bookmarks yet: Bookmarks ▸ Add Bookmark (Ctrl+B) keeps the pose shown.</source>
        <translation>Још нема обележивача: Обележивачи ▸ Додај обележивач (Ctrl+B) памти приказани положај.</translation>
    </message>
    <message>
        <source>&amp;Presentation Mode</source>
        <translation>Режим &amp;презентације</translation>
    </message>
    <message>
        <source>Full screen, large text, high contrast: the linkage, its plot and the sliders (F5; Esc leaves)</source>
        <translation>Цео екран, крупан текст, висок контраст: механизам, његов дијаграм и клизачи (F5; излаз Esc)</translation>
    </message>
    <message>
        <source>&amp;Text Size</source>
        <translation>Величина &amp;текста</translation>
    </message>
    <message>
        <source>Presentation mode: Esc or F5 leaves it; Page Up and Page Down step through the bookmarks.</source>
        <translation>Режим презентације: излаз Esc или F5; Page Up и Page Down листају обележиваче.</translation>
    </message>
    <message>
        <source>Equations</source>
        <translation>Једначине</translation>
    </message>
    <message>
        <source>New from &amp;Template</source>
        <translation>Ново из &amp;шаблона</translation>
    </message>
    <message>
        <source>Export &amp;Animation (GIF, MP4, WebM)…</source>
        <translation>Извези &amp;анимацију (GIF, MP4, WebM)…</translation>
    </message>
    <message>
        <source>5R (two driven cranks)</source>
        <translation>5R (две погонске полуге)</translation>
    </message>
    <message>
        <source>5R driven by two П-joints</source>
        <translation>5R с погоном од два П-зглоба</translation>
    </message>
    <message>
        <source>Constant orientation, 2 DOF, with two П-joints</source>
        <translation>Стална оријентација, 2 степена слободе, са два П-зглоба</translation>
    </message>
    <message>
        <source>3-RP̲R (three struts)</source>
        <translation>3-RP̲R (три телескопска штапа)</translation>
    </message>
    <message>
        <source>3-R̲RR (three driven cranks)</source>
        <translation>3-R̲RR (три погонске полуге)</translation>
    </message>
    <message>
        <source>3-P̲RR (three driven sliders)</source>
        <translation>3-P̲RR (три погонска клизача)</translation>
    </message>
    <message>
        <source>2-P̲RR (two driven sliders, MOMA 3a)</source>
        <translation>2-P̲RR (два погонска клизача, MOMA 3a)</translation>
    </message>
    <message>
        <source>&amp;User Guide</source>
        <translation>&amp;Упутство</translation>
    </message>
    <message>
        <source>What&apos;s &amp;This?</source>
        <translation>Шта је &amp;ово?</translation>
    </message>
    <message>
        <source>The plots of this mechanism over the range of its input; the cursor marks the current pose. A right click saves a plot as a picture.</source>
        <translation>Графици овог механизма по опсегу његовог улаза; курсор означава тренутни положај. Клик десним тастером чува график као слику.</translation>
    </message>
    <message>
        <source>The workspace map: where the platform can go, coloured by the quantity chosen above it, with the singular curves. Click a point to move the platform there; the marker shows the current pose.</source>
        <translation>Мапа радног простора: где платформа може да стигне, обојена по величини изабраној изнад ње, са сингуларним кривама. Клик на тачку помера платформу тамо; ознака показује тренутни положај.</translation>
    </message>
    <message>
        <source>The linkage at its current pose. Drag a round handle to move a joint or the platform; the wheel zooms, the right button pans and F fits the mechanism. Faint ghosts are the other assembly modes: click one to switch to it. Limits and singular poses are told at the bottom.</source>
        <translation>Механизам у тренутном положају. Превуците округлу ручицу да померите зглоб или платформу; точкић увећава, десни тастер помера поглед, а F уклапа механизам. Бледе сенке су други начини склапања: клик на једну прелази на њу. О границама и сингуларним положајима се обавештава доле.</translation>
    </message>
    <message>
        <source>The joint variables: each slider and its number set one variable of the mechanism, and the pose follows at once. A value the mechanism cannot reach is refused with a message.</source>
        <translation>Унутрашње координате: сваки клизач и његов број задају једну координату механизма, а положај одмах следи. Вредност коју механизам не може да достигне одбија се поруком.</translation>
    </message>
    <message>
        <source>Play moves the chosen joint variable by itself over the range set here, at this speed, in a loop, forth and back or once. It stops at a limit or before a singular pose and says why.</source>
        <translation>Покретање само помера изабрану координату по овде задатом опсегу, овом брзином: у круг, напред и назад или једном. Зауставља се на граници или пре сингуларног положаја и каже зашто.</translation>
    </message>
    <message>
        <source>The design: every dimension and mode of the mechanism. Change a value and the linkage, the values, the plots and the maps follow; every change can be undone (Ctrl+Z).</source>
        <translation>Конструкција: све мере и режими механизма. Промените вредност и шема, вредности, графици и мапе ће је пратити; свака измена може да се опозове (Ctrl+Z).</translation>
    </message>
    <message>
        <source>The values at this pose: joint variables, the Jacobian, its determinant and condition number and what the actuators deliver, each with its unit and meaning. At a singular pose a value that is infinite reads ∞ and one that is undefined reads —.</source>
        <translation>Вредности у овом положају: координате, јакобијан, његова детерминанта и број условљености и оно што дају актуатори, свака са јединицом и значењем. У сингуларном положају бесконачна вредност се приказује као ∞, а неодређена као —.</translation>
    </message>
    <message>
        <source>The mobility of the mechanism: its degrees of freedom counted by the structural formulas and by the rank of its loop equations at this pose, and where the formulas are wrong.</source>
        <translation>Покретљивост механизма: број степени слободе по структурним формулама и по рангу једначина затворених контура у овом положају, и где формуле греше.</translation>
    </message>
    <message>
        <source>The governing equations of this mechanism with the source document&apos;s equation numbers, each followed by the same equation with the current numbers put in; they follow the pose.</source>
        <translation>Основне једначине овог механизма са бројевима једначина изворног документа, а после сваке иста једначина са уписаним тренутним бројевима; прате положај.</translation>
    </message>
    <message>
        <source>The mechanism in 3D at the current pose: drag to turn it, right-drag to pan, the wheel zooms and a double-click fits it. The sliders drive it as they drive the 2D view.</source>
        <translation>Механизам у 3D у тренутном положају: превлачење га окреће, превлачење десним тастером помера, точкић увећава, а двоструки клик уклапа. Клизачи га покрећу као и поглед 2D.</translation>
    </message>
    <message>
        <source>The assembly and working modes: the mode of the current pose, and a button for each other mode the mechanism can take here, which switches to it.</source>
        <translation>Начини склапања и радни режими: режим тренутног положаја и дугме за сваки други режим који механизам овде може да заузме; оно прелази на њега.</translation>
    </message>
    <message>
        <source>Ellipses</source>
        <translation>Елипсе</translation>
    </message>
    <message>
        <source>Velocity and force polygons and ellipses at the platform point (V)</source>
        <translation>Полигони и елипсе брзине и силе у тачки платформе (V)</translation>
    </message>
    <message>
        <source>&amp;Velocity and Force Shapes</source>
        <translation>Облици &amp;брзине и силе</translation>
    </message>
    <message>
        <source>The velocity and force polygons (solid) and ellipses (dashed) the actuators give at the platform point, to the scale of the legend (V)</source>
        <translation>Полигони (пуне линије) и елипсе (испрекидане) брзине и силе које актуатори дају у тачки платформе, у размери легенде (V)</translation>
    </message>
    <message>
        <source>This design states no actuator limits, so there are no velocity and force shapes to draw.</source>
        <translation>Ова конструкција не задаје границе актуатора, па нема облика брзине и силе за цртање.</translation>
    </message>
    <message>
        <source>The velocity and force shapes cannot be scaled for this design: its home pose is singular.</source>
        <translation>Облици брзине и силе не могу се сразмерити за ову конструкцију: њен почетни положај је сингуларан.</translation>
    </message>
    <message>
        <source>Tolerances</source>
        <translation>Толеранције</translation>
    </message>
    <message>
        <source>What the actuators must deliver at the platform; the workspace map shows where it holds</source>
        <translation>Шта погони морају да дају на платформи; мапа радног простора показује где је то испуњено</translation>
    </message>
    <message>
        <source>The requirements are kept with the design; this mechanism has no workspace map to show where they hold.</source>
        <translation>Захтеви су сачувани уз конструкцију; овај механизам нема мапу радног простора која би показала где су испуњени.</translation>
    </message>
    <message>
        <source>Re&amp;quirements…</source>
        <translation>&amp;Захтеви…</translation>
    </message>
    <message>
        <source>Presentation P&amp;lot</source>
        <translation>Гра&amp;фикон презентације</translation>
    </message>
    <message>
        <source>Values</source>
        <translation>Вредности</translation>
    </message>
    <message>
        <source>The output of this mechanism is one angle: its speed, torque and stiffness are in “Values”; there is no platform point to draw shapes at.</source>
        <translation>Излаз овог механизма је један угао: његова брзина, момент и крутост су у „Вредностима”; нема тачке платформе на којој би се цртали облици.</translation>
    </message>
</context>
<context>
    <name>pkm::MobilityPanel</name>
    <message>
        <source>✓ right</source>
        <translation>✓ тачно</translation>
    </message>
    <message>
        <source>⚠ wrong</source>
        <translation>⚠ нетачно</translation>
    </message>
    <message numerus="yes">
        <source>W = %1, but the rank gives M = %2: the formula counts %3 equations per loop, and %n of them are redundant.</source>
        <translation>
            <numerusform>W = %1, али ранг даје M = %2: формула узима %3 као број једначина по контури, а %n од њих је сувишна.</numerusform>
            <numerusform>W = %1, али ранг даје M = %2: формула узима %3 као број једначина по контури, а %n од њих су сувишне.</numerusform>
            <numerusform>W = %1, али ранг даје M = %2: формула узима %3 као број једначина по контури, а %n од њих је сувишно.</numerusform>
        </translation>
    </message>
    <message>
        <source>A negative W rightly says “rigid”, but it is not the mobility: M = 0.</source>
        <translation>Негативно W с правом каже „крут“, али то није покретљивост: M = 0.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Classroom example: the spatial parallelogram.&lt;/b&gt; The П-joint prototype&apos;s hinged parallelogram (a = 170 mm, b = 68 mm): four parallel revolute axes, counted as a spatial chain.</source>
        <translation>&lt;b&gt;Пример за наставу: просторни паралелограм.&lt;/b&gt; Зглобни паралелограм прототипа П-зглоба (a = 170 mm, b = 68 mm): четири паралелне осе обртних парова, посматране као просторни ланац.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Classroom example: the Bennett linkage.&lt;/b&gt; Four skew revolute axes, opposite links equal (a = 100 mm, b ≈ 188 mm) with twists α = 30°, β = 70° and a/sin α = b/sin β.</source>
        <translation>&lt;b&gt;Пример за наставу: Бенетов механизам.&lt;/b&gt; Четири мимоилазне осе обртних парова, наспрамни чланови једнаки (a = 100 mm, b ≈ 188 mm), са угловима увијања α = 30°, β = 70° и a/sin α = b/sin β.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Classroom example: a general spatial 4R loop.&lt;/b&gt; Four revolute axes in general position, without Bennett&apos;s proportions: the same counts as the Bennett linkage.</source>
        <translation>&lt;b&gt;Пример за наставу: општа просторна контура 4R.&lt;/b&gt; Четири осе обртних парова у општем положају, без Бенетових пропорција: исто бројање као код Бенетовог механизма.</translation>
    </message>
    <message>
        <source>the %1</source>
        <translation>%1</translation>
    </message>
    <message>
        <source>the ground (%1)</source>
        <translation>постоље (%1)</translation>
    </message>
    <message numerus="yes">
        <source>&lt;b&gt;Links&lt;/b&gt;: %1 and %n moving link(s), n = %n: %2.</source>
        <translation>
            <numerusform>&lt;b&gt;Чланови&lt;/b&gt;: %1 и %n покретни члан, n = %n: %2.</numerusform>
            <numerusform>&lt;b&gt;Чланови&lt;/b&gt;: %1 и %n покретна члана, n = %n: %2.</numerusform>
            <numerusform>&lt;b&gt;Чланови&lt;/b&gt;: %1 и %n покретних чланова, n = %n: %2.</numerusform>
        </translation>
    </message>
    <message>
        <source>&lt;b&gt;Pairs&lt;/b&gt;: %1.</source>
        <translation>&lt;b&gt;Парови&lt;/b&gt;: %1.</translation>
    </message>
    <message>
        <source>none</source>
        <translation>нема</translation>
    </message>
    <message>
        <source>Actuated: %1.</source>
        <translation>Погоњени: %1.</translation>
    </message>
    <message numerus="yes">
        <source>&lt;b&gt;Loops&lt;/b&gt;: %n independent loop(s), L = %n.</source>
        <translation>
            <numerusform>&lt;b&gt;Контуре&lt;/b&gt;: %n независна контура, L = %n.</numerusform>
            <numerusform>&lt;b&gt;Контуре&lt;/b&gt;: %n независне контуре, L = %n.</numerusform>
            <numerusform>&lt;b&gt;Контуре&lt;/b&gt;: %n независних контура, L = %n.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>&lt;b&gt;Idle freedoms&lt;/b&gt;: %n (a part spinning about its own axis), counted in every number below.</source>
        <translation>
            <numerusform>&lt;b&gt;Пасивни степени слободе&lt;/b&gt;: %n (део који се окреће око сопствене осе); урачунати у сваки број испод.</numerusform>
            <numerusform>&lt;b&gt;Пасивни степени слободе&lt;/b&gt;: %n (део који се окреће око сопствене осе); урачунати у сваки број испод.</numerusform>
            <numerusform>&lt;b&gt;Пасивни степени слободе&lt;/b&gt;: %n (део који се окреће око сопствене осе); урачунати у сваки број испод.</numerusform>
        </translation>
    </message>
    <message>
        <source>At this pose the mechanism gains an instantaneous freedom (singularity).</source>
        <translation>У овом положају механизам добија тренутни степен слободе (сингуларитет).</translation>
    </message>
    <message>
        <source>The rank of the loop equations drops from %1 to %2: the instantaneous mobility is %3, the mobility next to this pose %4.</source>
        <translation>Ранг једначина затварања пада са %1 на %2: тренутна покретљивост је %3, покретљивост у близини овог положаја %4.</translation>
    </message>
    <message>
        <source>With the actuators locked the mechanism can still move instantaneously here: it gains a freedom the actuators do not control (a direct singularity).</source>
        <translation>Са закоченим погонима механизам овде и даље може тренутно да се помери: добија степен слободе који погони не контролишу (сингуларитет директне кинематике).</translation>
    </message>
    <message>
        <source>⚠ Singular pose</source>
        <translation>⚠ Сингуларан положај</translation>
    </message>
    <message>
        <source>Chebyshev (planar chains)</source>
        <translation>Чебишев (равански ланци)</translation>
    </message>
    <message>
        <source>Does not apply: the chain has pairs that do not move in its plane.</source>
        <translation>Не примењује се: ланац има парове који се не крећу у његовој равни.</translation>
    </message>
    <message>
        <source>Does not apply: a spatial chain.</source>
        <translation>Не примењује се: просторни ланац.</translation>
    </message>
    <message>
        <source>Somov–Malyshev (spatial chains)</source>
        <translation>Сомов–Малишев (просторни ланци)</translation>
    </message>
    <message>
        <source>The source document prints the last term as “+ P₁”: a typo. A pair of class 1 takes away one freedom, so − P₁.</source>
        <translation>Изворни рад последњи члан штампа као „+ P₁“: то је штампарска грешка. Пар класе 1 одузима један степен слободе, дакле − P₁.</translation>
    </message>
    <message>
        <source>⚠ Here it matters: with + P₁ the formula would give W = %1.</source>
        <translation>⚠ Овде је то битно: са + P₁ формула би дала W = %1.</translation>
    </message>
    <message>
        <source>No loop equation is redundant: the structural count holds.</source>
        <translation>Ниједна једначина затварања није сувишна: структурно бројање важи.</translation>
    </message>
    <message>
        <source>Bennett&apos;s proportions (opposite links equal, a/sin α = b/sin β) make them depend on the others, so the linkage moves although the count says it cannot.</source>
        <translation>Бенетове пропорције (наспрамни чланови једнаки, a/sin α = b/sin β) чине их зависним од осталих, па се механизам креће иако бројање каже да не може.</translation>
    </message>
    <message>
        <source>the joint axes are parallel, so each loop moves in a plane and imposes only 3 of its 6 equations.</source>
        <translation>осе зглобова су паралелне, па се свака контура креће у равни и намеће само 3 од својих 6 једначина.</translation>
    </message>
    <message>
        <source>%1 independent equations already hold all %1 freedoms of the pairs: a rigid chain with constraints to spare.</source>
        <translation>независних једначина већ има %1 — оне држе све степене слободе парова (F = %1): крут ланац са сувишним везама.</translation>
    </message>
    <message>
        <source>the pairs&apos; axes lie in a special way (parallel, or meeting in a point), so some equations repeat others: an overconstrained chain.</source>
        <translation>осе парова леже на посебан начин (паралелне су или се секу у једној тачки), па неке једначине понављају друге: ланац са сувишним везама.</translation>
    </message>
    <message numerus="yes">
        <source>%n redundant loop equation(s): %1</source>
        <translation>
            <numerusform>%n сувишна једначина затварања: %1</numerusform>
            <numerusform>%n сувишне једначине затварања: %1</numerusform>
            <numerusform>%n сувишних једначина затварања: %1</numerusform>
        </translation>
    </message>
    <message>
        <source>From the rank of the constraint Jacobian</source>
        <translation>Из ранга Јакобијеве матрице веза</translation>
    </message>
    <message numerus="yes">
        <source>An open chain, no loop: nothing holds the %n freedom(s) of its pairs, M = F = %n.</source>
        <translation>
            <numerusform>Отворен ланац, без контура: ништа не ограничава %n степен слободе његових парова, M = F = %n.</numerusform>
            <numerusform>Отворен ланац, без контура: ништа не ограничава %n степена слободе његових парова, M = F = %n.</numerusform>
            <numerusform>Отворен ланац, без контура: ништа не ограничава %n степени слободе његових парова, M = F = %n.</numerusform>
        </translation>
    </message>
    <message>
        <source>F = %1 freedoms of the pairs; 6L = %2 loop equations.</source>
        <translation>F = %1 — број степени слободе парова; 6L = %2 — број једначина затварања.</translation>
    </message>
    <message>
        <source>At this pose: rank %1 of %2 → %3 (instantaneous).</source>
        <translation>У овом положају: ранг %1 од %2 → %3 (тренутна).</translation>
    </message>
    <message>
        <source>Next to it: rank %1 of %2 → %3.</source>
        <translation>У близини: ранг %1 од %2 → %3.</translation>
    </message>
    <message>
        <source>rank %1 of %2 loop equations → %3</source>
        <translation>ранг %1 од %2 једначина затварања → %3</translation>
    </message>
    <message>
        <source>Mobility M = %1</source>
        <translation>Покретљивост M = %1</translation>
    </message>
    <message>
        <source>(%1 at this pose)</source>
        <translation>(%1 у овом положају)</translation>
    </message>
    <message>
        <source>Actuation</source>
        <translation>Погони</translation>
    </message>
    <message numerus="yes">
        <source>%n actuated freedom(s)</source>
        <translation>
            <numerusform>%n погоњен степен слободе</numerusform>
            <numerusform>%n погоњена степена слободе</numerusform>
            <numerusform>%n погоњених степени слободе</numerusform>
        </translation>
    </message>
    <message>
        <source>No pair is actuated.</source>
        <translation>Ниједан пар није погоњен.</translation>
    </message>
    <message>
        <source>⚠ Under-actuated by %1:</source>
        <translation>⚠ Недостаје погона (%1):</translation>
    </message>
    <message numerus="yes">
        <source>%1 for mobility %2; with the actuators locked, it keeps %n freedom(s).</source>
        <translation>
            <numerusform>%1 за покретљивост %2; са закоченим погонима задржава %n степен слободе.</numerusform>
            <numerusform>%1 за покретљивост %2; са закоченим погонима задржава %n степена слободе.</numerusform>
            <numerusform>%1 за покретљивост %2; са закоченим погонима задржава %n степени слободе.</numerusform>
        </translation>
    </message>
    <message>
        <source>Redundantly actuated: %1 for mobility %2.</source>
        <translation>Сувишан број погона: %1 за покретљивост %2.</translation>
    </message>
    <message>
        <source>✓ Fully actuated:</source>
        <translation>✓ Потпуно погоњен:</translation>
    </message>
    <message>
        <source>%1 for mobility %2.</source>
        <translation>%1 за покретљивост %2.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Verdict&lt;/b&gt;: %1</source>
        <translation>&lt;b&gt;Закључак&lt;/b&gt;: %1</translation>
    </message>
    <message>
        <source>Analyse:</source>
        <translation>Анализа:</translation>
    </message>
    <message>
        <source>This mechanism</source>
        <translation>Овај механизам</translation>
    </message>
    <message>
        <source>Example: spatial parallelogram</source>
        <translation>Пример: просторни паралелограм</translation>
    </message>
    <message>
        <source>Example: Bennett linkage</source>
        <translation>Пример: Бенетов механизам</translation>
    </message>
    <message>
        <source>Example: general spatial 4R (rigid)</source>
        <translation>Пример: општи просторни 4R (крут)</translation>
    </message>
    <message>
        <source>Classroom examples: chains where the structural formulas fail, and one where the counts predict the truth</source>
        <translation>Примери за наставу: ланци за које структурне формуле греше и један за који бројање даје тачан одговор</translation>
    </message>
    <message>
        <source>No mechanism to analyse.</source>
        <translation>Нема механизма за анализу.</translation>
    </message>
    <message>
        <source>Analysing…</source>
        <translation>Анализирам…</translation>
    </message>
    <message numerus="yes">
        <source>%n revolute</source>
        <translation>
            <numerusform>%n обртни</numerusform>
            <numerusform>%n обртна</numerusform>
            <numerusform>%n обртних</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n prismatic</source>
        <translation>
            <numerusform>%n призматични</numerusform>
            <numerusform>%n призматична</numerusform>
            <numerusform>%n призматичних</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n screw</source>
        <translation>
            <numerusform>%n завојни</numerusform>
            <numerusform>%n завојна</numerusform>
            <numerusform>%n завојних</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n cylindrical</source>
        <translation>
            <numerusform>%n цилиндрични</numerusform>
            <numerusform>%n цилиндрична</numerusform>
            <numerusform>%n цилиндричних</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n planar cam</source>
        <translation>
            <numerusform>%n равански брегасти</numerusform>
            <numerusform>%n раванска брегаста</numerusform>
            <numerusform>%n раванских брегастих</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n spherical</source>
        <translation>
            <numerusform>%n сферни</numerusform>
            <numerusform>%n сферна</numerusform>
            <numerusform>%n сферних</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>At this pose the mechanism gains %n instantaneous freedoms (singularity).</source>
        <translation>
            <numerusform>У овом положају механизам добија %n тренутни степен слободе (сингуларитет).</numerusform>
            <numerusform>У овом положају механизам добија %n тренутна степена слободе (сингуларитет).</numerusform>
            <numerusform>У овом положају механизам добија %n тренутних степени слободе (сингуларитет).</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>pkm::ModeBar</name>
    <message>
        <source>Modes: %1</source>
        <translation>Режими: %1</translation>
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
        <translation>Пребаци: %1. Механизам остаје у тренутном режиму док не кликнете овде или на његов провидни обрис у приказу.</translation>
    </message>
    <message>
        <source>→ %1, %2:</source>
        <translation>→ %1, %2:</translation>
    </message>
    <message>
        <source>The mode the mechanism is in.</source>
        <translation>Режим у коме је механизам.</translation>
    </message>
</context>
<context>
    <name>pkm::OxGlidePanel</name>
    <message>
        <source>Form:</source>
        <translation>Облик:</translation>
    </message>
    <message>
        <source>O — extended</source>
        <translation>O — опружени</translation>
    </message>
    <message>
        <source>X — crossed</source>
        <translation>X — укрштени</translation>
    </message>
    <message>
        <source>Work in the extended form: the rods splay outwards from the platform.</source>
        <translation>Рад у опруженом облику: штапови се од платформе шире ка споља.</translation>
    </message>
    <message>
        <source>Work in the crossed form: the slider pairs pass each other and the rods cross.</source>
        <translation>Рад у укрштеном облику: парови клизача се мимоилазе, а штапови се укрштају.</translation>
    </message>
    <message>
        <source>Animate crossing</source>
        <translation>Анимирај прелаз</translation>
    </message>
    <message>
        <source>Raise the platform towards the O↔X crossing (y = l, x_CD − x_AB = s) and stop short of the singular pose there.</source>
        <translation>Подиже платформу ка прелазу O↔X (y = l, x_CD − x_AB = s) и зауставља се пре сингуларног положаја.</translation>
    </message>
    <message>
        <source>Workspace O / X</source>
        <translation>Радни простор O / X</translation>
    </message>
    <message>
        <source>Singularity map</source>
        <translation>Мапа сингуларитета</translation>
    </message>
    <message>
        <source>The crossing stopped: the design changed.</source>
        <translation>Прелаз је заустављен: конструкција је промењена.</translation>
    </message>
    <message>
        <source>Workspaces of the O and X forms (fig. 5)</source>
        <translation>Радни простори облика O и X (сл. 5)</translation>
    </message>
    <message>
        <source>O↔X crossing y = l: singular</source>
        <translation>Прелаз O↔X y = l: сингуларитет</translation>
    </message>
    <message>
        <source>The crossing stopped: the pose was moved.</source>
        <translation>Прелаз је заустављен: положај је померен.</translation>
    </message>
    <message>
        <source>Crossing stopped.</source>
        <translation>Прелаз је заустављен.</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Заустави</translation>
    </message>
    <message>
        <source>Raising the platform towards the O↔X crossing at y = l…</source>
        <translation>Платформа се подиже ка прелазу O↔X на y = l…</translation>
    </message>
    <message>
        <source>&lt;b&gt;Stopped %1 short of the singular pose.&lt;/b&gt; At y = l = %2 the slider pairs stand at x_CD − x_AB = s: the rods are perpendicular to the guides and parallel to each other, so the platform can swing sideways while the sliders hold still (a combined singularity), and it may leave in either form. Here the rods are at %3° to the guides. Passing needs the platform guided through that point: choose the form to leave in.</source>
        <translation>&lt;b&gt;Заустављено %1 пре сингуларног положаја.&lt;/b&gt; На y = l = %2 парови клизача стоје на x_CD − x_AB = s: штапови су управни на вођице и паралелни међусобно, па платформа може да се њише у страну док клизачи мирују (комбиновани сингуларитет) и да изађе у било ком облику. Овде су штапови под углом од %3° према вођицама. За пролаз платформа мора бити вођена кроз ту тачку: изаберите облик у коме ће изаћи.</translation>
    </message>
    <message>
        <source>The crossing stopped %1 below y = l, short of the singular pose x_CD − x_AB = s.</source>
        <translation>Прелаз је заустављен %1 испод y = l, пре сингуларног положаја x_CD − x_AB = s.</translation>
    </message>
    <message>
        <source>Leave in the extended (O) form</source>
        <translation>Изађи у опруженом облику (O)</translation>
    </message>
    <message>
        <source>Leave in the crossed (X) form</source>
        <translation>Изађи у укрштеном облику (X)</translation>
    </message>
    <message>
        <source>Go back in the crossed (X) form</source>
        <translation>Врати се у укрштеном облику (X)</translation>
    </message>
    <message>
        <source>Go back in the extended (O) form</source>
        <translation>Врати се у опруженом облику (O)</translation>
    </message>
    <message>
        <source>Switched to the crossed (X) form at the same platform position.</source>
        <translation>Прешло се на укрштени облик (X) у истом положају платформе.</translation>
    </message>
    <message>
        <source>Switched to the extended (O) form at the same platform position.</source>
        <translation>Прешло се на опружени облик (O) у истом положају платформе.</translation>
    </message>
    <message>
        <source>The crossed (X) form is not available at this pose.</source>
        <translation>Укрштени облик (X) није доступан у овом положају.</translation>
    </message>
    <message>
        <source>The extended (O) form is not available at this pose.</source>
        <translation>Опружени облик (O) није доступан у овом положају.</translation>
    </message>
    <message>
        <source>The platform is back at y = %1, in the crossed (X) form.</source>
        <translation>Платформа је враћена на y = %1, у укрштеном облику (X).</translation>
    </message>
    <message>
        <source>The platform is back at y = %1, in the extended (O) form.</source>
        <translation>Платформа је враћена на y = %1, у опруженом облику (O).</translation>
    </message>
    <message>
        <source>Lowering the platform in the crossed (X) form…</source>
        <translation>Платформа се спушта у укрштеном облику (X)…</translation>
    </message>
    <message>
        <source>Lowering the platform in the extended (O) form…</source>
        <translation>Платформа се спушта у опруженом облику (O)…</translation>
    </message>
</context>
<context>
    <name>pkm::PJointPlots</name>
    <message>
        <source>Geometry</source>
        <translation>Геометрија</translation>
    </message>
    <message>
        <source>Jacobian</source>
        <translation>Јакобијан</translation>
    </message>
    <message>
        <source>Actuator</source>
        <translation>Актуатор</translation>
    </message>
    <message>
        <source>Fig. 8 — diagonal length d(θ), (2)</source>
        <translation>Сл. 8 — дужина дијагонале d(θ), (2)</translation>
    </message>
    <message>
        <source>Fig. 9 — passive angle φ(θ)</source>
        <translation>Сл. 9 — пасивни угао φ(θ)</translation>
    </message>
    <message>
        <source>Fig. 10 — transmission angle μ(θ)</source>
        <translation>Сл. 10 — угао преноса μ(θ)</translation>
    </message>
    <message>
        <source>Fig. 11 — Jacobian J(θ) = ∂d/∂θ, (7)</source>
        <translation>Сл. 11 — јакобијан J(θ) = ∂d/∂θ, (7)</translation>
    </message>
    <message>
        <source>Fig. 12 — inverse Jacobian J⁻¹(θ), (8)</source>
        <translation>Сл. 12 — инверзни јакобијан J⁻¹(θ), (8)</translation>
    </message>
    <message>
        <source>Fig. 15 — output resolution Δθ = Δd/J</source>
        <translation>Сл. 15 — резолуција излаза Δθ = Δd/J</translation>
    </message>
    <message>
        <source>Fig. 16 — output speed θ̇ = ḋ_max/J</source>
        <translation>Сл. 16 — брзина излаза θ̇ = ḋ_max/J</translation>
    </message>
    <message>
        <source>Fig. 17 — output torque T = J·F_max, (13)</source>
        <translation>Сл. 17 — излазни момент T = J·F_max, (13)</translation>
    </message>
    <message>
        <source>a = %1 mm, k = %2, θ %3°…%4°; family at the same a</source>
        <translation>a = %1 mm, k = %2, θ %3°…%4°; фамилија при истом a</translation>
    </message>
    <message>
        <source>diagonal OA from the base OB</source>
        <translation>дијагонала OA у односу на основицу OB</translation>
    </message>
    <message>
        <source>at A, diagonal to crank; J = a·sin μ</source>
        <translation>у тачки A, између дијагонале и полуге; J = a·sin μ</translation>
    </message>
    <message>
        <source>ḋ = J·θ̇; a = %1 mm, k = %2</source>
        <translation>ḋ = J·θ̇; a = %1 mm, k = %2</translation>
    </message>
    <message>
        <source>θ̇ = J⁻¹·ḋ; J⁻¹ → ∞ at θ = ±90°</source>
        <translation>θ̇ = J⁻¹·ḋ; J⁻¹ → ∞ при θ = ±90°</translation>
    </message>
    <message>
        <source>one motor step Δd = %1 mm</source>
        <translation>један корак мотора Δd = %1 mm</translation>
    </message>
    <message>
        <source>at the maximum linear speed ḋ_max = %1 mm/s</source>
        <translation>при највећој линијској брзини ḋ_max = %1 mm/s</translation>
    </message>
    <message>
        <source>F_max = %1 N; motor torque T_M = %2 N·m at any θ (15)</source>
        <translation>F_max = %1 N; момент мотора T_M = %2 N·m за свако θ (15)</translation>
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
        <translation>ова конструкција (k = %1)</translation>
    </message>
    <message>
        <source>beyond its θ range</source>
        <translation>изван њеног опсега θ</translation>
    </message>
    <message>
        <source>k = %1</source>
        <translation>k = %1</translation>
    </message>
    <message>
        <source>recommended %1°…%2° (J ≥ %3 % of best)</source>
        <translation>препоручено %1°…%2° (J ≥ %3 % од најбољег)</translation>
    </message>
    <message>
        <source>steep region</source>
        <translation>стрма област</translation>
    </message>
    <message>
        <source>μ &lt; %1°: force almost along the crank</source>
        <translation>μ &lt; %1°: сила делује скоро дуж полуге</translation>
    </message>
</context>
<context>
    <name>pkm::PictureDialog</name>
    <message>
        <source>PNG pictures (*.png)</source>
        <translation>PNG слике (*.png)</translation>
    </message>
    <message>
        <source>SVG drawings (*.svg)</source>
        <translation>SVG цртежи (*.svg)</translation>
    </message>
    <message>
        <source>PDF documents (*.pdf)</source>
        <translation>PDF документи (*.pdf)</translation>
    </message>
    <message>
        <source>%1 × %2 pixels is not a picture size: each side must be from %3 to %4.</source>
        <translation>%1 × %2 пиксела није величина слике: свака страница мора бити од %3 до %4.</translation>
    </message>
    <message>
        <source>%1 dpi is not a resolution: it must be from %2 to %3 dpi.</source>
        <translation>%1 dpi није резолуција: мора бити од %2 до %3 dpi.</translation>
    </message>
    <message>
        <source>The %1 picture could not be drawn.</source>
        <translation>Слика %1 није могла да се нацрта.</translation>
    </message>
    <message>
        <source>There is not enough memory for a picture of %1 × %2 pixels.</source>
        <translation>Нема довољно меморије за слику од %1 × %2 пиксела.</translation>
    </message>
    <message>
        <source>Drawn by %1</source>
        <translation>Нацртано у програму %1</translation>
    </message>
    <message>
        <source>“%1” is not a picture format: the file name must end in .png, .svg or .pdf.</source>
        <translation>„%1“ није формат слике: име датотеке мора да се завршава са .png, .svg или .pdf.</translation>
    </message>
    <message>
        <source>There is no plot to draw.</source>
        <translation>Нема графикона за цртање.</translation>
    </message>
    <message>
        <source>“%1” could not be opened for writing: %2.</source>
        <translation>„%1“ није могуће отворити за упис: %2.</translation>
    </message>
    <message>
        <source>The picture could not be written to “%1”: %2.</source>
        <translation>Слику није могуће уписати у „%1“: %2.</translation>
    </message>
    <message>
        <source>“%1” could not be saved: %2.</source>
        <translation>„%1“ није могуће сачувати: %2.</translation>
    </message>
    <message>
        <source>Save picture…</source>
        <translation>Сачувај слику…</translation>
    </message>
    <message>
        <source>Save this plot as a PNG picture, an SVG or a PDF drawing</source>
        <translation>Сачувај овај графикон као PNG слику или као SVG или PDF цртеж</translation>
    </message>
    <message>
        <source>Save Picture</source>
        <translation>Чување слике</translation>
    </message>
    <message>
        <source>Picture Size</source>
        <translation>Величина слике</translation>
    </message>
    <message>
        <source>%1 × %2</source>
        <translation>%1 × %2</translation>
    </message>
    <message>
        <source>As shown — %1</source>
        <translation>Као на екрану — %1</translation>
    </message>
    <message>
        <source>Twice as shown — %1</source>
        <translation>Двоструко веће — %1</translation>
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
        <translation>Произвољна</translation>
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
        <translation>SVG цртеж је скалабилан: величина му је у CSS пикселима.</translation>
    </message>
    <message>
        <source>The PDF&apos;s page is the size in pixels at this resolution.</source>
        <translation>Страница PDF-а има величину у пикселима при овој резолуцији.</translation>
    </message>
    <message>
        <source>Stored in the PNG: the size it prints at.</source>
        <translation>Уписује се у PNG и одређује величину при штампи.</translation>
    </message>
    <message>
        <source>&amp;Size:</source>
        <translation>&amp;Величина:</translation>
    </message>
    <message>
        <source>&amp;Width:</source>
        <translation>&amp;Ширина:</translation>
    </message>
    <message>
        <source>&amp;Height:</source>
        <translation>В&amp;исина:</translation>
    </message>
    <message>
        <source>&amp;Resolution:</source>
        <translation>&amp;Резолуција:</translation>
    </message>
    <message>
        <source>%1 × %2 mm</source>
        <translation>%1 × %2 mm</translation>
    </message>
    <message>
        <source>%1 × %2 pixels</source>
        <translation>%1 × %2 пиксела</translation>
    </message>
    <message>
        <source>An SVG drawing of %1 (CSS pixels), lines and text as vectors.</source>
        <translation>SVG цртеж од %1 (CSS пиксели), линије и текст као вектори.</translation>
    </message>
    <message>
        <source>A PDF page of %1: %2 at %3 dpi, lines and text as vectors.</source>
        <translation>PDF страница од %1: %2 при %3 dpi, линије и текст као вектори.</translation>
    </message>
    <message>
        <source>A PNG picture of %1; it prints at %2 at %3 dpi.</source>
        <translation>PNG слика од %1; штампа се као %2 при %3 dpi.</translation>
    </message>
</context>
<context>
    <name>pkm::PlanarParallelPanel</name>
    <message>
        <source>Add leg 3</source>
        <translation>Додај ногу 3</translation>
    </message>
    <message>
        <source>Remove leg 3</source>
        <translation>Уклони ногу 3</translation>
    </message>
    <message>
        <source>Change the platform</source>
        <translation>Промени платформу</translation>
    </message>
    <message>
        <source>Change the type of leg %1</source>
        <translation>Промени тип ноге %1</translation>
    </message>
    <message>
        <source>Change the working mode of leg %1</source>
        <translation>Промени радни режим ноге %1</translation>
    </message>
    <message>
        <source>Legs</source>
        <translation>Ноге</translation>
    </message>
    <message>
        <source>&amp;Platform:</source>
        <translation>&amp;Платформа:</translation>
    </message>
    <message>
        <source>Add leg</source>
        <translation>Додај ногу</translation>
    </message>
    <message>
        <source>A third leg, a strut opposite the other two: the platform becomes a free body (3 DOF).</source>
        <translation>Трећа нога, штап наспрам друге две: платформа постаје слободно тело (3 степена слободе).</translation>
    </message>
    <message>
        <source>Two legs: the platform becomes a point, or keeps a constant orientation if both legs are P̲RR or П̲RR.</source>
        <translation>Две ноге: платформа постаје тачка, или задржава сталну оријентацију ако су обе ноге P̲RR или П̲RR.</translation>
    </message>
    <message>
        <source>a point (2 legs, x and y)</source>
        <translation>тачка (2 ноге, x и y)</translation>
    </message>
    <message>
        <source>constant orientation (2 legs, x and y)</source>
        <translation>стална оријентација (2 ноге, x и y)</translation>
    </message>
    <message>
        <source>free body (3 legs, x, y and φ)</source>
        <translation>слободно тело (3 ноге, x, y и φ)</translation>
    </message>
    <message>
        <source>Leg %1:</source>
        <translation>Нога %1:</translation>
    </message>
    <message>
        <source>R̲RR: driven crank and link</source>
        <translation>R̲RR: погонска полуга и спојка</translation>
    </message>
    <message>
        <source>P̲RR: driven slider and link</source>
        <translation>P̲RR: погонски клизач и спојка</translation>
    </message>
    <message>
        <source>RP̲R: telescopic strut</source>
        <translation>RP̲R: телескопски штап</translation>
    </message>
    <message>
        <source>П̲RR: active П-joint and link</source>
        <translation>П̲RR: активни П-зглоб и спојка</translation>
    </message>
    <message>
        <source>The leg&apos;s joints from the base, the actuated one underlined.</source>
        <translation>Зглобови ноге од основе, погонски подвучен.</translation>
    </message>
    <message>
        <source>working mode +1</source>
        <translation>радни режим +1</translation>
    </message>
    <message>
        <source>working mode −1</source>
        <translation>радни режим −1</translation>
    </message>
    <message>
        <source>+1: the elbow left of the line from A to the platform point (P̲RR: the slider beyond the foot of the perpendicular).</source>
        <translation>+1: лакат лево од линије од A до тачке платформе (P̲RR: клизач иза подножја нормале).</translation>
    </message>
    <message>
        <source>point</source>
        <translation>тачка</translation>
    </message>
    <message>
        <source>constant orientation</source>
        <translation>стална оријентација</translation>
    </message>
    <message>
        <source>free body</source>
        <translation>слободно тело</translation>
    </message>
</context>
<context>
    <name>pkm::PlayBar</name>
    <message>
        <source>Pause</source>
        <translation>Пауза</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Покрени</translation>
    </message>
    <message>
        <source>/s</source>
        <translation>/s</translation>
    </message>
    <message>
        <source>Play: move the chosen joint variable by itself (stops at a limit or before a singular pose)</source>
        <translation>Покрени: изабрана променљива зглоба се креће сама (зауставља се на граници или пре сингуларног положаја)</translation>
    </message>
    <message>
        <source>from</source>
        <translation>од</translation>
    </message>
    <message>
        <source>to</source>
        <translation>до</translation>
    </message>
    <message>
        <source>speed</source>
        <translation>брзина</translation>
    </message>
    <message>
        <source>Loop</source>
        <translation>У круг</translation>
    </message>
    <message>
        <source>Forth and back</source>
        <translation>Напред и назад</translation>
    </message>
    <message>
        <source>Once</source>
        <translation>Једном</translation>
    </message>
    <message>
        <source>At the end of the range: start again, turn back, or stop</source>
        <translation>На крају опсега: почни поново, врати се или стани</translation>
    </message>
</context>
<context>
    <name>pkm::Player</name>
    <message>
        <source>inverse</source>
        <translation>инверзне кинематике</translation>
    </message>
    <message>
        <source>direct</source>
        <translation>директне кинематике</translation>
    </message>
    <message>
        <source>combined</source>
        <translation>комбиновани</translation>
    </message>
    <message>
        <source>Play needs a range: “from” must be below “to” for %1, and the speed above 0.</source>
        <translation>За покретање је потребан опсег: за %1 „од” мора бити мање од „до”, а брзина већа од 0.</translation>
    </message>
    <message>
        <source>Play stopped before a singular pose (%1) at %2 = %3.</source>
        <translation>Покретање је заустављено пре сингуларног положаја (%1) при %2 = %3.</translation>
    </message>
    <message>
        <source>Play reached the end of its range.</source>
        <translation>Покретање је стигло до краја опсега.</translation>
    </message>
    <message>
        <source>Play turned back: %1</source>
        <translation>Покретање се вратило назад: %1</translation>
    </message>
    <message>
        <source>Play stopped close to a singular pose at %1 = %2.</source>
        <translation>Покретање је заустављено близу сингуларног положаја при %1 = %2.</translation>
    </message>
    <message>
        <source>Play turned back close to a singular pose at %1 = %2.</source>
        <translation>Покретање се вратило назад близу сингуларног положаја при %1 = %2.</translation>
    </message>
    <message>
        <source>Play turned back before a singular pose (%1) at %2 = %3.</source>
        <translation>Покретање се вратило назад пре сингуларног положаја (%1) при %2 = %3.</translation>
    </message>
</context>
<context>
    <name>pkm::Renderer3D</name>
    <message>
        <source>No OpenGL context is current.</source>
        <translation>Нема текућег OpenGL контекста.</translation>
    </message>
    <message>
        <source>The driver offers OpenGL %1%2.%3; the 3D view needs OpenGL 3.3.</source>
        <translation>Драјвер нуди OpenGL %1%2.%3, а 3D приказу је потребан OpenGL 3.3.</translation>
    </message>
    <message>
        <source>The OpenGL 3.3 core functions could not be resolved.</source>
        <translation>Функције језгра OpenGL 3.3 нису могле да се учитају.</translation>
    </message>
    <message>
        <source>OpenGL %1.%2 (%3), %4</source>
        <translation>OpenGL %1.%2 (%3), %4</translation>
    </message>
    <message>
        <source>The 3D view&apos;s shaders could not be built: %1</source>
        <translation>Шејдери 3D приказа нису могли да се изграде: %1</translation>
    </message>
    <message>
        <source>A picture of %1 × %2 pixels is not possible: the largest is %3 × %3.</source>
        <translation>Слика од %1 × %2 пиксела није могућа: највећа је %3 × %3.</translation>
    </message>
    <message>
        <source>The OpenGL driver could not make a framebuffer of %1 × %2 pixels.</source>
        <translation>OpenGL драјвер није могао да направи бафер кадра од %1 × %2 пиксела.</translation>
    </message>
    <message>
        <source>No OpenGL context could be created on the “%1” display platform.</source>
        <translation>OpenGL контекст није могао да се направи на платформи приказа „%1“.</translation>
    </message>
    <message>
        <source>The driver offers OpenGL %1%2.%3 only.</source>
        <translation>Драјвер нуди само OpenGL %1%2.%3.</translation>
    </message>
    <message>
        <source>The OpenGL context could not be made current on an offscreen surface.</source>
        <translation>OpenGL контекст није могао да постане текући на површини ван екрана.</translation>
    </message>
</context>
<context>
    <name>pkm::RequirementsDialog</name>
    <message>
        <source>Requirements</source>
        <translation>Захтеви</translation>
    </message>
    <message>
        <source>What the actuators must deliver at the platform. The workspace map “where the requirements hold” shows, in green, where every checked one does, from the actuators&apos; limits in the design.</source>
        <translation>Шта погони морају да дају на платформи. Мапа радног простора „где су захтеви испуњени“ зеленом бојом показује где је испуњен сваки означени, према границама погона у конструкцији.</translation>
    </message>
    <message>
        <source>This design states no actuator limits: there is nothing to require.</source>
        <translation>Ова конструкција не задаје границе погона: нема шта да се захтева.</translation>
    </message>
    <message>
        <source>Also required (from the file, kept as it is): %1</source>
        <translation>Такође се захтева (из датотеке, задржано какво јесте): %1</translation>
    </message>
</context>
<context>
    <name>pkm::SetParameterCommand</name>
    <message>
        <source>Change %1</source>
        <translation>Промени %1</translation>
    </message>
</context>
<context>
    <name>pkm::SweepPlotsPanel</name>
    <message>
        <source>&amp;Quantity:</source>
        <translation>&amp;Величина:</translation>
    </message>
    <message>
        <source>%1 against %2</source>
        <translation>%1 (на апсциси: %2)</translation>
    </message>
</context>
<context>
    <name>pkm::TolerancePanel</name>
    <message>
        <source>Give a tolerance to at least one parameter.</source>
        <translation>Задајте толеранцију бар једном параметру.</translation>
    </message>
    <message>
        <source>First-order worst case at this pose: |Δx| ≤ %1 (%2).</source>
        <translation>Најгори случај у првој апроксимацији у овом положају: |Δx| ≤ %1 (%2).</translation>
    </message>
    <message>
        <source>Monte Carlo</source>
        <translation>Монте Карло</translation>
    </message>
    <message>
        <source>Solving %1 designs within the tolerances…</source>
        <translation>Решавање %1 конструкција у оквиру толеранција…</translation>
    </message>
    <message>
        <source>Monte Carlo cancelled.</source>
        <translation>Монте Карло је отказан.</translation>
    </message>
    <message>
        <source>%1 of %2 samples did not assemble (%3 %).</source>
        <translation>%1 од %2 узорака се није склопило (%3 %).</translation>
    </message>
    <message>
        <source>No sample assembled: the distribution is undefined.</source>
        <translation>Ниједан узорак се није склопио: расподела није дефинисана.</translation>
    </message>
    <message>
        <source>Monte Carlo |Δx|: mean %1, σ %2, max %3. %4</source>
        <translation>Монте Карло |Δx|: средња вредност %1, σ %2, макс. %3. %4</translation>
    </message>
    <message>
        <source>|Δx| (%1)</source>
        <translation>|Δx| (%1)</translation>
    </message>
    <message>
        <source>samples</source>
        <translation>узорци</translation>
    </message>
    <message>
        <source>This mechanism has no planar workspace to map.</source>
        <translation>Овај механизам нема равански радни простор за мапу.</translation>
    </message>
    <message>
        <source>Worst-case map</source>
        <translation>Мапа најгорег случаја</translation>
    </message>
    <message>
        <source>Mapping the worst-case error over the workspace…</source>
        <translation>Мапирање најгоре грешке по радном простору…</translation>
    </message>
    <message>
        <source>Map cancelled.</source>
        <translation>Мапа је отказана.</translation>
    </message>
    <message>
        <source>Worst case over the workspace: %1 to %2 (%3 cells; dark: small, bright: large).</source>
        <translation>Најгори случај по радном простору: од %1 до %2 (%3 ћелија; тамно: мало, светло: велико).</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Параметар</translation>
    </message>
    <message>
        <source>Tolerance</source>
        <translation>Толеранција</translation>
    </message>
    <message>
        <source>Error part</source>
        <translation>Удео грешке</translation>
    </message>
    <message>
        <source>Share</source>
        <translation>Удео</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>Параметри</translation>
    </message>
    <message>
        <source>Monte Carlo and map</source>
        <translation>Монте Карло и мапа</translation>
    </message>
    <message>
        <source>Samples:</source>
        <translation>Узорака:</translation>
    </message>
    <message>
        <source>Normal (tol = 3σ)</source>
        <translation>Нормална (толеранција = 3σ)</translation>
    </message>
    <message>
        <source>Draw normal samples with the tolerance as 3σ instead of uniform ones within ±tol</source>
        <translation>Узимај нормалне узорке са толеранцијом као 3σ уместо равномерних у оквиру ±толеранције</translation>
    </message>
    <message>
        <source>Solve many designs drawn within the tolerances at this pose (fixed seed)</source>
        <translation>Реши много конструкција узетих у оквиру толеранција у овом положају (фиксно семе)</translation>
    </message>
    <message>
        <source>Map</source>
        <translation>Мапа</translation>
    </message>
    <message>
        <source>The first-order worst case over the workspace</source>
        <translation>Најгори случај у првој апроксимацији по радном простору</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Обриши</translation>
    </message>
    <message>
        <source>Remove every tolerance (undoable)</source>
        <translation>Уклони све толеранције (може се опозвати)</translation>
    </message>
</context>
<context>
    <name>pkm::ValuesTable</name>
    <message>
        <source>Pose</source>
        <translation>Положај</translation>
    </message>
    <message>
        <source>Jacobian</source>
        <translation>Јакобијан</translation>
    </message>
    <message>
        <source>Derived</source>
        <translation>Изведене величине</translation>
    </message>
    <message>
        <source>none</source>
        <translation>нема</translation>
    </message>
    <message>
        <source>inverse</source>
        <translation>инверзни</translation>
    </message>
    <message>
        <source>direct</source>
        <translation>директни</translation>
    </message>
    <message>
        <source>combined</source>
        <translation>комбиновани</translation>
    </message>
    <message>
        <source>Quantity</source>
        <translation>Величина</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Вредност</translation>
    </message>
    <message>
        <source>Meaning</source>
        <translation>Опис</translation>
    </message>
    <message>
        <source>Singularity</source>
        <translation>Сингуларитет</translation>
    </message>
    <message>
        <source>class</source>
        <translation>класа</translation>
    </message>
    <message>
        <source>none, inverse, direct or combined</source>
        <translation>нема, инверзни, директни или комбиновани</translation>
    </message>
    <message>
        <source>%1 (margin %2)</source>
        <translation>%1 (удаљеност %2)</translation>
    </message>
    <message>
        <source>Capability</source>
        <translation>Могућности погона</translation>
    </message>
    <message>
        <source>Capability: as at a singular pose</source>
        <translation>Могућности: као у сингуларном положају</translation>
    </message>
    <message>
        <source>near inverse</source>
        <translation>близу инверзног</translation>
    </message>
    <message>
        <source>near direct</source>
        <translation>близу директног</translation>
    </message>
    <message>
        <source>near combined</source>
        <translation>близу комбинованог</translation>
    </message>
    <message>
        <source>Point at a row to read its meaning in full.</source>
        <translation>Поставите показивач на ред да прочитате његово значење у целости.</translation>
    </message>
</context>
<context>
    <name>pkm::VariablePanel</name>
    <message>
        <source>input, actuated</source>
        <translation>улаз, са погоном</translation>
    </message>
    <message>
        <source>input</source>
        <translation>улаз</translation>
    </message>
    <message>
        <source>output</source>
        <translation>излаз</translation>
    </message>
    <message>
        <source>Drag to set %1 (%2), from %3 to %4</source>
        <translation>Превуците да подесите %1 (%2), од %3 до %4</translation>
    </message>
</context>
<context>
    <name>pkm::VideoWriter</name>
    <message>
        <source>A video is %1 to %2 pixels wide and %1 to %3 high, in even numbers (e.g. 1280x720 or 1920x1080), not %4x%5.</source>
        <translation>Видео је широк од %1 до %2 и висок од %1 до %3 пиксела, у парним бројевима (нпр. 1280x720 или 1920x1080), а не %4x%5.</translation>
    </message>
    <message>
        <source>Cannot write &apos;%1&apos;: %2.</source>
        <translation>Не може да се упише „%1“: %2.</translation>
    </message>
    <message>
        <source>unknown error</source>
        <translation>непозната грешка</translation>
    </message>
    <message>
        <source>This build of FFmpeg&apos;s libavformat cannot write %1 files.</source>
        <translation>Ова верзија FFmpeg-ове библиотеке libavformat не може да пише %1 датотеке.</translation>
    </message>
    <message>
        <source>FFmpeg is out of memory.</source>
        <translation>FFmpeg-у је понестало меморије.</translation>
    </message>
    <message>
        <source>FFmpeg could not start the %1 encoder (%2): %3.</source>
        <translation>FFmpeg није могао да покрене %1 кодер (%2): %3.</translation>
    </message>
    <message>
        <source>FFmpeg&apos;s libavcodec here has no H.264 encoder: MP4 needs libx264 (Debian&apos;s libavcodec has it).</source>
        <translation>FFmpeg-ов libavcodec овде нема H.264 кодер: за MP4 је потребан libx264 (Debian-ов libavcodec га има).</translation>
    </message>
    <message>
        <source>FFmpeg&apos;s libavcodec here has no VP9 or VP8 encoder: WebM needs libvpx (Debian&apos;s libavcodec has it).</source>
        <translation>FFmpeg-ов libavcodec овде нема VP9 ни VP8 кодер: за WebM је потребан libvpx (Debian-ов libavcodec га има).</translation>
    </message>
    <message>
        <source>FFmpeg&apos;s libswscale cannot convert the frames to YUV 4:2:0.</source>
        <translation>FFmpeg-ов libswscale не може да претвори кадрове у YUV 4:2:0.</translation>
    </message>
    <message>
        <source>The video is not open.</source>
        <translation>Видео није отворен.</translation>
    </message>
    <message>
        <source>A video needs at least one frame.</source>
        <translation>Видео мора да има бар један кадар.</translation>
    </message>
</context>
<context>
    <name>pkm::View3DPanel</name>
    <message>
        <source>Names</source>
        <translation>Имена</translation>
    </message>
    <message>
        <source>The names of the joints (A, B, … as in the 2D view) over the model</source>
        <translation>Имена зглобова (A, B, … као у 2D приказу) преко модела</translation>
    </message>
    <message>
        <source>Fit</source>
        <translation>Уклопи</translation>
    </message>
    <message>
        <source>Show the whole mechanism (F, or double-click)</source>
        <translation>Прикажи цео механизам (F или двоструки клик)</translation>
    </message>
    <message>
        <source>Front</source>
        <translation>Спреда</translation>
    </message>
    <message>
        <source>Look at the mechanism plane, as the 2D view does (1)</source>
        <translation>Поглед на раван механизма, као у 2D приказу (1)</translation>
    </message>
    <message>
        <source>Top</source>
        <translation>Одозго</translation>
    </message>
    <message>
        <source>Look down from above (7)</source>
        <translation>Поглед одозго надоле (7)</translation>
    </message>
    <message>
        <source>Side</source>
        <translation>Са стране</translation>
    </message>
    <message>
        <source>Look from the right (3)</source>
        <translation>Поглед здесна (3)</translation>
    </message>
    <message>
        <source>Isometric</source>
        <translation>Изометрија</translation>
    </message>
    <message>
        <source>Look from the front, right and above at once</source>
        <translation>Поглед истовремено спреда, здесна и одозго</translation>
    </message>
    <message>
        <source>Perspective</source>
        <translation>Перспектива</translation>
    </message>
    <message>
        <source>Perspective when on, orthographic (true to scale) when off (5)</source>
        <translation>Укључено — перспектива, искључено — ортогонална пројекција (у размери) (5)</translation>
    </message>
    <message>
        <source>Save picture…</source>
        <translation>Сачувај слику…</translation>
    </message>
    <message>
        <source>Save the 3D view as a PNG picture at twice its size</source>
        <translation>Сачувај 3D приказ као PNG слику двоструке величине</translation>
    </message>
    <message>
        <source>%1 × %2 pixels is not a picture size: each side must be from 16 to 8000.</source>
        <translation>%1 × %2 пиксела није исправна величина слике: свака страница мора бити од 16 до 8000.</translation>
    </message>
    <message>
        <source>The picture could not be rendered. %1</source>
        <translation>Слика није могла да се исцрта. %1</translation>
    </message>
    <message>
        <source>“%1” could not be opened for writing: %2</source>
        <translation>Датотека „%1“ није могла да се отвори за упис: %2</translation>
    </message>
    <message>
        <source>The picture could not be written to “%1”.</source>
        <translation>Слика није могла да се упише у „%1“.</translation>
    </message>
    <message>
        <source>“%1” could not be saved: %2</source>
        <translation>Датотека „%1“ није могла да се сачува: %2</translation>
    </message>
    <message>
        <source>Save picture</source>
        <translation>Сачувај слику</translation>
    </message>
    <message>
        <source>PNG pictures (*.png)</source>
        <translation>PNG слике (*.png)</translation>
    </message>
    <message>
        <source>%1 × %2 pixels</source>
        <translation>%1 × %2 пиксела</translation>
    </message>
    <message>
        <source>%1 (twice the view)</source>
        <translation>%1 (двоструко већа од приказа)</translation>
    </message>
    <message>
        <source>Picture size:</source>
        <translation>Величина слике:</translation>
    </message>
</context>
<context>
    <name>pkm::ViewPicture</name>
    <message>
        <source>Save 2D View Picture</source>
        <translation>Сачувај слику 2D приказа</translation>
    </message>
</context>
<context>
    <name>pkm::WorkspaceMapView</name>
    <message>
        <source>No mechanism.</source>
        <translation>Нема механизма.</translation>
    </message>
    <message>
        <source>No planar workspace: the outputs of this mechanism are not a point of the plane, so there is no workspace map to show.</source>
        <translation>Нема равног радног простора: излазне координате овог механизма нису тачка равни, па нема мапе радног простора за приказ.</translation>
    </message>
    <message>
        <source>Workspace map</source>
        <translation>Мапа радног простора</translation>
    </message>
    <message>
        <source>Workspace empty in the design&apos;s working and assembly modes</source>
        <translation>Радни простор је празан у радном режиму и начину склапања ове конструкције</translation>
    </message>
    <message>
        <source>κ(J), log scale (colours end at %1)</source>
        <translation>κ(J), логаритамска скала (боје до %1)</translation>
    </message>
    <message>
        <source>det J (colours clipped at ±%1)</source>
        <translation>det J (боје ограничене на ±%1)</translation>
    </message>
    <message>
        <source>The colours end at the 98th percentile of κ(J) over the workspace, %1; κ → ∞ at the singularities.</source>
        <translation>Скала боја се завршава на 98. перцентилу κ(J) у радном простору, %1; у сингуларитетима κ → ∞.</translation>
    </message>
    <message>
        <source>The colours are clipped at ±%1, the larger of the 5th and 95th percentiles of |det J| over the workspace: det J → ±∞ at inverse singularities, 0 at direct ones.</source>
        <translation>Боје су ограничене на ±%1, већи од 5. и 95. перцентила |det J| у радном простору: у сингуларитетима инверзне кинематике det J → ±∞, у сингуларитетима директне кинематике 0.</translation>
    </message>
    <message>
        <source>workspace boundary</source>
        <translation>граница радног простора</translation>
    </message>
    <message>
        <source>: none</source>
        <translation>: нема</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>inverse singularity</source>
        <translation>сингуларитет инверзне кинематике</translation>
    </message>
    <message>
        <source>direct singularity</source>
        <translation>сингуларитет директне кинематике</translation>
    </message>
    <message>
        <source>%1: boundary, %2</source>
        <translation>%1: граница, %2</translation>
    </message>
    <message>
        <source> (%1%2 %)</source>
        <translation> (%1%2 %)</translation>
    </message>
    <message>
        <source>&amp;Map:</source>
        <translation>&amp;Мапа:</translation>
    </message>
    <message>
        <source>condition number κ(J)</source>
        <translation>број условљености κ(J)</translation>
    </message>
    <message>
        <source>computing…</source>
        <translation>рачунам…</translation>
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
        <translation>Радни простор %1 · опсег оријентације φ од %2° до %3°</translation>
    </message>
    <message>
        <source>orientation range of φ (°): the angles that hold the platform</source>
        <translation>опсег оријентације φ (°): углови у којима ноге држе платформу</translation>
    </message>
    <message>
        <source>At each point, the total width of the platform angles φ at which the legs can hold it there; the map&apos;s outline is the workspace at φ_map.</source>
        <translation>У свакој тачки укупна ширина углова платформе φ при којима је ноге могу држати ту; контура мапе је радни простор при φ_map.</translation>
    </message>
    <message>
        <source>orientation range of φ</source>
        <translation>опсег оријентације φ</translation>
    </message>
    <message>
        <source>force in the weakest direction</source>
        <translation>сила у најслабијем правцу</translation>
    </message>
    <message>
        <source>speed in the slowest direction</source>
        <translation>брзина у најспоријем правцу</translation>
    </message>
    <message>
        <source>worst resolution</source>
        <translation>најгора резолуција</translation>
    </message>
    <message>
        <source>stiffness in the weakest direction</source>
        <translation>крутост у најслабијем правцу</translation>
    </message>
    <message>
        <source>where the requirements hold</source>
        <translation>где су захтеви испуњени</translation>
    </message>
    <message>
        <source>Requirements met in %1 of the workspace %2 (%3 %)</source>
        <translation>Захтеви испуњени на %1 од радног простора %2 (%3 %)</translation>
    </message>
    <message>
        <source>green: every requirement holds; grey: one fails</source>
        <translation>зелено: сви захтеви испуњени; сиво: један није</translation>
    </message>
    <message>
        <source>Required: %1</source>
        <translation>Захтева се: %1</translation>
    </message>
    <message>
        <source>%1 (%2): %3, colours end at %4</source>
        <translation>%1 (%2): %3, боје до %4</translation>
    </message>
    <message>
        <source>What the actuators deliver at each point of the workspace, from their limits in the design: 0 or ∞ exactly at a singularity. Every cell is the value of the pose solved there.</source>
        <translation>Шта погони дају у свакој тачки радног простора, према својим границама у конструкцији: тачно 0 или ∞ у сингуларном положају. Свака ћелија је вредност положаја решеног у тој тачки.</translation>
    </message>
    <message>
        <source>No requirements stated (Edit ▸ Requirements…): the whole workspace %1 meets them</source>
        <translation>Нису задати захтеви (Уређивање ▸ Захтеви…): цео радни простор %1 их испуњава</translation>
    </message>
    <message>
        <source>State what the actuators must deliver with Edit ▸ Requirements….</source>
        <translation>Задајте шта погони морају да дају у менију Уређивање ▸ Захтеви….</translation>
    </message>
    <message>
        <source>The first-order worst-case error of the platform point at each point of the workspace, from the tolerances of the Tolerances panel: ∞ at a direct singularity.</source>
        <translation>Највећа грешка тачке платформе у првом приближењу у свакој тачки радног простора, према толеранцијама панела „Толеранције”: ∞ у сингуларитету директне кинематике.</translation>
    </message>
    <message>
        <source>worst-case error from the tolerances</source>
        <translation>највећа грешка од толеранција</translation>
    </message>
    <message>
        <source>Workspace %1 · %2 from %3 to %4%5 at the grid points</source>
        <translation>Радни простор %1 · %2 од %3 до %4%5 у чворовима мреже</translation>
    </message>
    <message>
        <source>%1 at φ = %2</source>
        <translation>%1 при φ = %2</translation>
    </message>
    <message>
        <source>Workspace %1 · %2 from %3 to %4 at the grid points</source>
        <translation>Радни простор %1 · %2 од %3 до %4 у чворовима мреже</translation>
    </message>
    <message>
        <source>%1 at φ = %2, not the pose&apos;s φ</source>
        <translation>%1 при φ = %2 (положај има други угао φ)</translation>
    </message>
    <message>
        <source>range of φ (°)</source>
        <translation>опсег φ (°)</translation>
    </message>
    <message>
        <source>κ(J), log scale</source>
        <translation>κ(J), лог. скала</translation>
    </message>
    <message>
        <source>Workspace %1</source>
        <translation>Радни простор %1</translation>
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
        <translation>Упореди радни простор са:</translation>
    </message>
    <message>
        <source>Pin this design</source>
        <translation>Запамти ову конструкцију</translation>
    </message>
    <message>
        <source>Keep the current design&apos;s workspace as the comparison, then change the design and see both outlines.</source>
        <translation>Задржава радни простор тренутне конструкције за поређење, па можете да промените конструкцију и видите обе контуре.</translation>
    </message>
    <message>
        <source>nothing</source>
        <translation>ничим</translation>
    </message>
    <message>
        <source>pinned: %1</source>
        <translation>запамћена: %1</translation>
    </message>
    <message>
        <source>pinned</source>
        <translation>запамћена</translation>
    </message>
</context>
<context>
    <name>pkm::designfile</name>
    <message>
        <source>%1 is not valid JSON (%2 at byte %3).</source>
        <translation>%1 није исправан JSON (%2 на бајту %3).</translation>
    </message>
    <message>
        <source>%1 is not a PKM Studio design file.</source>
        <translation>%1 није датотека конструкције програма PKM Studio.</translation>
    </message>
    <message>
        <source>%1 was written by a newer PKM Studio (format version %2; this version reads up to %3).</source>
        <translation>%1 је записан новијом верзијом програма PKM Studio (верзија формата %2; ова верзија чита до %3).</translation>
    </message>
    <message>
        <source>%1 has no valid format version.</source>
        <translation>%1 нема исправну верзију формата.</translation>
    </message>
    <message>
        <source>%1 names an unknown mechanism kind &apos;%2&apos;.</source>
        <translation>%1 наводи непознату врсту механизма „%2“.</translation>
    </message>
    <message>
        <source>%1: unknown parameter &apos;%2&apos;.</source>
        <translation>%1: непознат параметар „%2“.</translation>
    </message>
    <message>
        <source>%1: parameter &apos;%2&apos; is not a number.</source>
        <translation>%1: параметар „%2“ није број.</translation>
    </message>
    <message>
        <source>%1: parameter &apos;%2&apos; must be a number or one of %3, not &apos;%4&apos;.</source>
        <translation>%1: параметар „%2“ мора бити број или једна од вредности %3, а не „%4“.</translation>
    </message>
    <message>
        <source>%1: pose value &apos;%2&apos; is not a number.</source>
        <translation>%1: вредност положаја „%2“ није број.</translation>
    </message>
    <message>
        <source>the pose&apos;s %1 = %2 %4 does not agree with its inputs, which give %3 %4.</source>
        <translation>вредност положаја %1 = %2 %4 не слаже се са улазним координатама, које дају %3 %4.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is neither a preset id (see &apos;pkm list&apos;) nor a design file.</source>
        <translation>„%1“ није ни ознака шаблона (видети „pkm list“) ни датотека конструкције.</translation>
    </message>
    <message>
        <source>Cannot open %1: %2.</source>
        <translation>Није могуће отворити %1: %2.</translation>
    </message>
    <message>
        <source>Cannot write %1: %2.</source>
        <translation>Није могуће уписати %1: %2.</translation>
    </message>
    <message>
        <source>Unknown parameter &apos;%1&apos; (see &apos;pkm show&apos;).</source>
        <translation>Непознат параметар „%1“ (видети „pkm show“).</translation>
    </message>
    <message>
        <source>Unknown pose variable &apos;%1&apos;.</source>
        <translation>Непозната променљива положаја „%1“.</translation>
    </message>
    <message>
        <source>Give either the actuated inputs or the outputs of the pose, not both.</source>
        <translation>Задајте или погонске (улазне) или излазне координате положаја, али не обе.</translation>
    </message>
    <message>
        <source>%1: “bookmarks” is not a list.</source>
        <translation>%1: „bookmarks” није листа.</translation>
    </message>
    <message>
        <source>%1 has more than %2 bookmarks.</source>
        <translation>%1 има више од %2 обележивача.</translation>
    </message>
    <message>
        <source>%1: a bookmark&apos;s name is longer than %2 characters.</source>
        <translation>%1: име обележивача је дуже од %2 знакова.</translation>
    </message>
    <message>
        <source>%1: bookmark “%2” has an invalid pose value &apos;%3&apos;.</source>
        <translation>%1: обележивач „%2” има неважећу вредност положаја „%3”.</translation>
    </message>
    <message>
        <source>%1: “tolerances” is not an object.</source>
        <translation>%1: „tolerances” није објекат.</translation>
    </message>
    <message>
        <source>%1 has more than %2 tolerances.</source>
        <translation>%1 има више од %2 толеранција.</translation>
    </message>
    <message>
        <source>it is not a number</source>
        <translation>то није број</translation>
    </message>
    <message>
        <source>%1: the tolerance of &apos;%2&apos; is refused: %3</source>
        <translation>%1: толеранција за „%2” је одбијена: %3</translation>
    </message>
    <message>
        <source>%1: “requirements” is not a list of texts.</source>
        <translation>%1: „requirements“ није листа текстова.</translation>
    </message>
    <message>
        <source>%1: “requirements” has more than %2 entries.</source>
        <translation>%1: „requirements“ има више од %2 ставки.</translation>
    </message>
    <message>
        <source>%1: “requirements” holds an entry that is not a text of at most %2 characters.</source>
        <translation>%1: „requirements“ садржи ставку која није текст од највише %2 знакова.</translation>
    </message>
    <message>
        <source>%1: “requirements”: %2</source>
        <translation>%1: „requirements“: %2</translation>
    </message>
    <message>
        <source>%1 is larger than %2 MiB, the most a design file may be.</source>
        <translation>%1 је већа од %2 MiB, колико највише датотека конструкције сме да има.</translation>
    </message>
    <message>
        <source>%1: the title is longer than %2 characters, the most a design keeps.</source>
        <translation>%1: наслов је дужи од %2 знакова, колико највише конструкција чува.</translation>
    </message>
    <message>
        <source>%1: the description is longer than %2 characters, the most a design keeps.</source>
        <translation>%1: опис је дужи од %2 знакова, колико највише конструкција чува.</translation>
    </message>
</context>
<context>
    <name>presets</name>
    <message>
        <source>Planar five-bar linkage (example)</source>
        <translation>Равански петочлани механизам (пример)</translation>
    </message>
    <message>
        <source>Four-bar linkage example (crank-rocker 40/120/100/140 mm)</source>
        <translation>Пример зглобног четвороугла (полуга–клацкалица 40/120/100/140 mm)</translation>
    </message>
    <message>
        <source>MOMA configuration 3a (γ₁ = −5°, γ₂ = +5°)</source>
        <translation>MOMA, конфигурација 3a (γ₁ = −5°, γ₂ = +5°)</translation>
    </message>
    <message>
        <source>Configuration of fig. 3a: R₁ = (−100, 0) mm, R₂ = (100, 0) mm, guides turned from the vertical by γ₁ = −5° and γ₂ = +5° (α_i = 270° + γ_i), so they open downwards. Links l₁ = l₂ = 195 mm, strokes h = 200 mm (p from 0 to 200 mm, measured from R_i along the guide). Both legs work with p_i = B_i − √(B_i² − C_i), the platform below the sliders. The document finds no direct singularities in this workspace.</source>
        <translation>Конфигурација са сл. 3a: R₁ = (−100, 0) mm, R₂ = (100, 0) mm, вођице заокренуте од вертикале за γ₁ = −5° и γ₂ = +5° (α_i = 270° + γ_i), тако да се шире наниже. Спојке l₁ = l₂ = 195 mm, ходови h = 200 mm (p од 0 до 200 mm, мерено од R_i дуж вођице). Обе гране раде са p_i = B_i − √(B_i² − C_i), платформа је испод клизача. Документ не налази сингуларитете директне кинематике у овом радном простору.</translation>
    </message>
    <message>
        <source>MOMA configuration 3b (γ₁ = +5°, γ₂ = −5°)</source>
        <translation>MOMA, конфигурација 3b (γ₁ = +5°, γ₂ = −5°)</translation>
    </message>
    <message>
        <source>Configuration of fig. 3b: as 3a with the guides turned the other way, γ₁ = +5° and γ₂ = −5°, so they close downwards. Links l₁ = l₂ = 195 mm, strokes h = 200 mm (p from 0 to 200 mm, measured from R_i along the guide). The document finds no direct singularities in this workspace.</source>
        <translation>Конфигурација са сл. 3b: као 3a, са вођицама заокренутим на другу страну, γ₁ = +5° и γ₂ = −5°, тако да се сужавају наниже. Спојке l₁ = l₂ = 195 mm, ходови h = 200 mm (p од 0 до 200 mm, мерено од R_i дуж вођице). Документ не налази сингуларитете директне кинематике у овом радном простору.</translation>
    </message>
    <message>
        <source>MOMA configuration 3c (interpreted)</source>
        <translation>MOMA, конфигурација 3c (тумачење)</translation>
    </message>
    <message>
        <source>Interpreted: the document describes 3c in two ways that do not agree (the guides along the axes, or α = 225°/315° turned by β through the matrices (15–16)), and its figure is missing; this preset takes the first. Configuration of fig. 3c: R₁ = (250, 0) mm with α₁ = 180° and R₂ = (0, 250) mm with α₂ = 270°, the guides along the axes towards the corner. Links l₁ = l₂ = 195 mm, strokes h = 200 mm (p from 0 to 200 mm, measured from R_i along the guide). Here both legs take the document&apos;s root p_i = B_i − √…; every inverse singularity lies on x = 195 mm or y = 195 mm (a link perpendicular to its guide), where the document puts them, at the edge of the other assembly mode&apos;s region near (195, 195) mm; the direct singularity needs both slider joints at the origin, beyond the strokes.</source>
        <translation>Тумачење: документ описује 3c на два начина који се не слажу (вођице дуж оса, или α = 225°/315° заокренуте за β матрицама (15–16)), а слика недостаје; овај шаблон узима први. Конфигурација са сл. 3c: R₁ = (250, 0) mm са α₁ = 180° и R₂ = (0, 250) mm са α₂ = 270°, вођице дуж оса ка углу. Спојке l₁ = l₂ = 195 mm, ходови h = 200 mm (p од 0 до 200 mm, мерено од R_i дуж вођице). Овде обе гране узимају корен из документа p_i = B_i − √…; сви сингуларитети инверзне кинематике леже на x = 195 mm или y = 195 mm (спојка управна на своју вођицу), где их документ и поставља, на ивици области другог начина склапања близу (195, 195) mm; сингуларитет директне кинематике захтева да оба зглоба клизача буду у координатном почетку, изван ходова.</translation>
    </message>
    <message>
        <source>MOMA configuration 3d (interpreted)</source>
        <translation>MOMA, конфигурација 3d (тумачење)</translation>
    </message>
    <message>
        <source>Interpreted: the document describes 3d in two ways that do not agree (the guides along the axes, or α = 225°/315° turned by β through the matrices (15–16)), and its figure is missing; this preset takes the first. Configuration of fig. 3d: R₁ = (117, 0) mm with α₁ = 0° and R₂ = (0, 117) mm with α₂ = 90°, the guides along the axes away from the corner, the platform between them near the origin. Links l₁ = l₂ = 195 mm, strokes h = 200 mm (p from 0 to 200 mm, measured from R_i along the guide). Here both legs take the root p_i = B_i + √… that keeps the platform on the corner side of the sliders; the direct singularities (links stretched in line) bound the workspace on the far side.</source>
        <translation>Тумачење: документ описује 3d на два начина који се не слажу (вођице дуж оса, или α = 225°/315° заокренуте за β матрицама (15–16)), а слика недостаје; овај шаблон узима први. Конфигурација са сл. 3d: R₁ = (117, 0) mm са α₁ = 0° и R₂ = (0, 117) mm са α₂ = 90°, вођице дуж оса у смеру од угла, платформа између њих близу координатног почетка. Спојке l₁ = l₂ = 195 mm, ходови h = 200 mm (p од 0 до 200 mm, мерено од R_i дуж вођице). Овде обе гране узимају корен p_i = B_i + √… који држи платформу са стране угла у односу на клизаче; сингуларитети директне кинематике (спојке опружене у линију) ограничавају радни простор са удаљене стране.</translation>
    </message>
    <message>
        <source>O-X glide prototype (l = 80 mm, s = 20 mm, L = 130 mm)</source>
        <translation>Прототип механизма O-X glide (l = 80 mm, s = 20 mm, L = 130 mm)</translation>
    </message>
    <message>
        <source>The rapid-prototyped O-X glide of the Novi Sad document: rods l = 80 mm, platform width s = 20 mm, transverse guides L = 130 mm (slider positions 0 to 130 mm), working in the extended (O) form. The guide spacing a = 15 mm and the longitudinal travel z = 0 to 150 mm are not given in the document and are chosen for the drawing; they do not change the planar workspace.</source>
        <translation>Брзо прототипизовани O-X glide механизам из новосадског документа: штапови l = 80 mm, ширина платформе s = 20 mm, попречне вођице L = 130 mm (положаји клизача од 0 до 130 mm), рад у опруженом (O) облику. Растојање између вођица a = 15 mm и уздужни ход z од 0 до 150 mm нису дати у документу и изабрани су за цртеж; они не мењају равански радни простор.</translation>
    </message>
    <message>
        <source>П-joint laboratory prototype (a = 170 mm, k = 0.4)</source>
        <translation>Лабораторијски прототип П-зглоба (a = 170 mm, k = 0,4)</translation>
    </message>
    <message>
        <source>The laboratory prototype of section 4.2: a = 170 mm, b = 68 mm (k = 0.4), θ = ±60°, driven by the hybrid stepper motor with integrated lead screw of Table 1 (lead 2.54 mm, 0.0127 mm/step, 50 mm/s, 130 N). The screw efficiency 0.4 is an assumption: Table 1 does not give it.</source>
        <translation>Лабораторијски прототип из одељка 4.2: a = 170 mm, b = 68 mm (k = 0,4), θ = ±60°, покретан хибридним корачним мотором са уграђеним завојним вретеном из табеле 1 (корак 2,54 mm, 0,0127 mm/корак, 50 mm/s, 130 N). Степен искоришћења вретена 0,4 је претпоставка: табела 1 га не наводи.</translation>
    </message>
    <message>
        <source>П-joint design study k = 0.3 (a = 1 m)</source>
        <translation>Пројектна студија П-зглоба, k = 0,3 (a = 1 m)</translation>
    </message>
    <message>
        <source>Design study of figures 8–12: a = 1 m, k = 0.3, θ over ±75°, with the stepper motor of Table 1.</source>
        <translation>Пројектна студија са слика 8–12: a = 1 m, k = 0,3, θ у опсегу ±75°, са корачним мотором из табеле 1.</translation>
    </message>
    <message>
        <source>П-joint design study k = 0.4 (a = 1 m)</source>
        <translation>Пројектна студија П-зглоба, k = 0,4 (a = 1 m)</translation>
    </message>
    <message>
        <source>Design study of figures 8–12: a = 1 m, k = 0.4, θ over ±75°, with the stepper motor of Table 1.</source>
        <translation>Пројектна студија са слика 8–12: a = 1 m, k = 0,4, θ у опсегу ±75°, са корачним мотором из табеле 1.</translation>
    </message>
    <message>
        <source>П-joint design study k = 0.5 (a = 1 m)</source>
        <translation>Пројектна студија П-зглоба, k = 0,5 (a = 1 m)</translation>
    </message>
    <message>
        <source>Design study of figures 8–12: a = 1 m, k = 0.5, θ over ±75°, with the stepper motor of Table 1.</source>
        <translation>Пројектна студија са слика 8–12: a = 1 m, k = 0,5, θ у опсегу ±75°, са корачним мотором из табеле 1.</translation>
    </message>
    <message>
        <source>A classroom five-bar chosen for PKM Studio (the four-bar and mobility document of Khabibullina, Khabibullin and Islamov shows the planar five-bar in its fig. 1 without dimensions). Ground AE = 100 mm; cranks AB = DE = 80 mm, driven at A and at E and turning fully; distal links BC = CD = 120 mm, meeting at the output point C. Chebyshev&apos;s count W = 3·4 − 2·5 = 2: the two crank angles θ₁, θ₄ fix C. Working modes elbows out (B to the left of A→C, D to the right of E→C), assembly mode C above BD (to the left of B→D). At C = (50, 150) mm each distal link is nearly perpendicular to its crank and the distal links nearly perpendicular to each other, so κ(J) ≈ 1.11; the workspace of these modes is bounded by the legs stretched or folded in line and, low between A and E, by a direct singularity where BC and CD come in line.</source>
        <translation>Наставни петочлани механизам изабран за PKM Studio (документ Хабибулине, Хабибулина и Исламова о зглобном четвороуглу и покретљивости приказује равански петочлани механизам на сл. 1 без димензија). Постоље AE = 100 mm; полуге AB = DE = 80 mm, погоњене у A и у E, окрећу се пуним кругом; крајње спојке BC = CD = 120 mm спајају се у излазној тачки C. По Чебишевљевој формули W = 3·4 − 2·5 = 2: два угла полуга θ₁, θ₄ одређују положај C. Радни режими „лактови ка споља“ (B лево од A→C, D десно од E→C), начин склапања C изнад BD (лево од B→D). За C = (50, 150) mm свака крајња спојка је скоро управна на своју полугу, а крајње спојке скоро управне једна на другу, па је κ(J) ≈ 1,11; радни простор ових режима ограничен је положајима у којима су гране опружене или склопљене у линију и, ниско између A и E, сингуларитетом директне кинематике где BC и CD долазе у исту линију.</translation>
    </message>
    <message>
        <source>An example crank-rocker chosen for PKM Studio: the four-bar document of Khabibullina, Khabibullin and Islamov gives no link lengths, so these are not the document&apos;s. Crank AB = 40 mm, coupler BC = 120 mm, rocker CD = 100 mm, ground AD = 140 mm: s + l = 180 mm &lt; p + q = 220 mm with the crank the shortest link, so the crank turns fully (α from 0° to 360°) and the rocker swings; the transmission angle stays between 53° and 110°. Open branch, ω₁ = 10 rad/s, coupler point M at the middle of BC.</source>
        <translation>Пример механизма полуга–клацкалица изабран за PKM Studio: документ Хабибулине, Хабибулина и Исламова о зглобном четвороуглу не даје дужине чланова, па ове вредности нису из документа. Полуга AB = 40 mm, спојка BC = 120 mm, клацкалица CD = 100 mm, постоље AD = 140 mm: s + l = 180 mm &lt; p + q = 220 mm, а полуга је најкраћи члан, па се полуга окреће пуним кругом (α од 0° до 360°), а клацкалица осцилује; угао преноса остаје између 53° и 110°. Отворена грана, ω₁ = 10 rad/s, тачка спојке M на средини BC.</translation>
    </message>
    <message>
        <source>Planar parallel: MOMA configuration 3a from two P̲RR legs</source>
        <translation>Равански паралелни: конфигурација MOMA 3a од две ноге P̲RR</translation>
    </message>
    <message>
        <source>MOMA configuration 3a (Vasilić and Živanović, the MOMA document, fig. 3a) rebuilt from the leg library: two P̲RR legs on guides from R₁ = (−100, 0) and R₂ = (100, 0) mm turned by γ = ∓5° from the vertical (α = 265°, 275°), strokes 0 to 200 mm, links 195 mm, both legs with q = B − √…, the platform right of C₁→C₂. Its poses and Jacobians are the MOMA kind&apos;s.</source>
        <translation>Конфигурација MOMA 3a (Васић и Живановић, документ о MOMA, сл. 3a) састављена из библиотеке ногу: две ноге P̲RR на вођицама од R₁ = (−100, 0) и R₂ = (100, 0) мм, закренутим за γ = ∓5° од вертикале (α = 265°, 275°), ходови од 0 до 200 мм, спојке 195 мм, обе ноге са q = B − √…, платформа десно од C₁→C₂. Њене позе и Јакобијеве матрице исте су као код врсте MOMA.</translation>
    </message>
    <message>
        <source>Planar parallel: a 3-RP̲R with six assembly modes</source>
        <translation>Равански паралелни: 3-RP̲R са шест начина склапања</translation>
    </message>
    <message>
        <source>The 3-RP̲R of Innocenti and Parenti-Castelli, studied by Zein, Wenger and Chablat (Non-singular assembly-mode changing motions for 3-RPR parallel manipulators, Mechanism and Machine Theory, 2008): base joints A₁ = (0, 0), A₂ = (15.91, 0), A₃ = (0, 10), platform sides B₁B₂ = 17.04, B₂B₃ = 16.54, B₃B₁ = 20.84. At the strut lengths 14.98, 15.38 and 12 its direct kinematics has six real solutions.</source>
        <translation>Механизам 3-RP̲R Иноћентија и Паренти-Кастелија, који су проучавали Зеин, Венгер и Шабла (чланак о прелазима између начина склапања 3-RP̲R без сингуларитета, часопис „Теорија механизама и машина”, 2008): зглобови основе A₁ = (0; 0), A₂ = (15,91; 0), A₃ = (0; 10), странице платформе B₁B₂ = 17,04, B₂B₃ = 16,54, B₃B₁ = 20,84. При дужинама шипки 14,98; 15,38 и 12 његова директна кинематика има шест реалних решења.</translation>
    </message>
    <message>
        <source>Planar parallel: a symmetric 3-R̲RR</source>
        <translation>Равански паралелни: симетрични 3-R̲RR</translation>
    </message>
    <message>
        <source>A symmetric 3-R̲RR chosen for PKM Studio, of the kind Gosselin and Angeles optimised (The optimum kinematic design of a planar three-degree-of-freedom parallel manipulator, 1988): base joints on an equilateral triangle of side 400 mm, cranks 120 mm, distal links 150 mm, an equilateral platform of circumradius 50 mm, every elbow left of A→P.</source>
        <translation>Симетрични 3-R̲RR изабран за PKM Studio, оне врсте коју су оптимизовали Госелен и Анђелес (чланак о оптималној кинематичкој синтези раванског паралелног манипулатора са три степена слободе, 1988): зглобови основе у теменима једнакостраничног троугла странице 400 мм, полуге 120 мм, дисталне спојке 150 мм, једнакостранична платформа полупречника описаног круга 50 мм, сваки лакат лево од A→P.</translation>
    </message>
    <message>
        <source>Planar parallel: a 5R driven by two П-joints</source>
        <translation>Равански паралелни: 5R погоњен са два П-зглоба</translation>
    </message>
    <message>
        <source>The planar 5R of the П-joint document&apos;s fig. 5 (Milutinović, Kokotović, Slavković and Živanović), each crank the crank of a laboratory П-joint (a = 170 mm, k = 0.4, θ = ±60°, diagonal 116.2 to 231.4 mm): pivots A₁ = (0, 0) and A₂ = (200, 0) mm, the П-joints&apos; bases turned by α = ±30°, distal links 200 mm.</source>
        <translation>Равански 5R са сл. 5 документа о П-зглобу (Милутиновић, Кокотовић, Славковић и Живановић), чија је свака полуга полуга лабораторијског П-зглоба (a = 170 мм, k = 0.4, θ = ±60°, дијагонала од 116.2 до 231.4 мм): ослонци A₁ = (0, 0) и A₂ = (200, 0) мм, основе П-зглобова закренуте за α = ±30°, дисталне спојке 200 мм.</translation>
    </message>
    <message>
        <source>Planar parallel: the five-bar example from two R̲RR legs</source>
        <translation>Равански паралелни: пример петочланог механизма од две ноге R̲RR</translation>
    </message>
    <message>
        <source>The five-bar example rebuilt from the leg library (the four-bar and mobility document of Khabibullina, Khabibullin and Islamov, fig. 1): two R̲RR legs from A₁ = (0, 0) and A₂ = (100, 0) mm, cranks 80 mm, distal links 120 mm, elbows out, the platform point above the elbows. Its poses and Jacobians are the five-bar kind&apos;s.</source>
        <translation>Пример петочланог механизма састављен из библиотеке ногу (документ о зглобном четвороуглу и покретљивости Хабибулине, Хабибулина и Исламова, сл. 1): две ноге R̲RR од A₁ = (0, 0) и A₂ = (100, 0) мм, полуге 80 мм, дисталне спојке 120 мм, лактови ка споља, тачка платформе изнад лактова. Његове позе и Јакобијеве матрице исте су као код врсте петочланог механизма.</translation>
    </message>
    <message>
        <source>Planar parallel: a translating platform driven by two П-joints</source>
        <translation>Равански паралелни: транслаторна платформа погоњена са два П-зглоба</translation>
    </message>
    <message>
        <source>The 2-DOF planar mechanism with a platform of constant orientation that Milutinović, Kokotović, Slavković and Živanović show among the applications of the П-joint (Механизам активног П-зглоба као еквивалента комбинације обртног зглоба и сегмента константне дужине, University of Belgrade, Faculty of Mechanical Engineering, 2014): two laboratory П-joints (a = 170 mm, k = 0.4, diagonal 116.5 to 231 mm) with their cranks at A₁ = (0, 0) and A₂ = (200, 0) mm and their bases turned by α = ±30°. The coupler of a П-joint keeps its direction, so a distal parallelogram of 200 mm from each coupler to the platform points B₁ = (−40, 0) and B₂ = (40, 0) mm keeps the platform&apos;s orientation. The second parallelogram repeats the first one&apos;s constraint: Chebyshev&apos;s count gives 1, the mobility is 2.</source>
        <translation>Равански механизам са два степена слободе и платформом сталне оријентације који Милутиновић, Кокотовић, Славковић и Живановић приказују међу применама П-зглоба („Механизам активног П-зглоба као еквивалента комбинације обртног зглоба и сегмента константне дужине”, Универзитет у Београду, Машински факултет, 2014): два лабораторијска П-зглоба (a = 170 mm, k = 0,4, дијагонала од 116,5 до 231 mm) са полугама у A₁ = (0, 0) и A₂ = (200, 0) mm и основама закренутим за α = ±30°. Спојка П-зглоба задржава свој правац, па дистални паралелограм од 200 mm од сваке спојке до тачака платформе B₁ = (−40, 0) и B₂ = (40, 0) mm задржава оријентацију платформе. Други паралелограм понавља везу првог: Чебишевљева формула даје 1, а покретљивост је 2.</translation>
    </message>
    <message>
        <source>Planar parallel: a symmetric 3-P̲RR</source>
        <translation>Равански паралелни: симетрични 3-P̲RR</translation>
    </message>
    <message>
        <source>A symmetric 3-P̲RR chosen for PKM Studio: three sliders driven along the sides of an equilateral triangle of side 346.41 mm (its corners A₁, A₂, A₃ 200 mm from the centre, each guide from Aᵢ towards the next corner, stroke 0 to 346.41 mm), distal links of 150 mm and an equilateral platform of circumradius 40 mm, every slider beyond the foot of the perpendicular from its platform point (working mode +1).</source>
        <translation>Симетрични 3-P̲RR изабран за PKM Studio: три клизача погоњена дуж страница једнакостраничног троугла странице 346.41 mm (његова темена A₁, A₂, A₃ на 200 mm од центра, свака вођица од Aᵢ ка следећем темену, ход од 0 до 346.41 mm), дисталне спојке од 150 mm и једнакостранична платформа полупречника описане кружнице 40 mm, сваки клизач иза подножја нормале из своје тачке платформе (радни режим +1).</translation>
    </message>
</context>
</TS>
