<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="ru_RU">
<context>
    <name>QAbstractSpinBox</name>
    <message>
        <source>Step &amp;down</source>
        <translation>Шаг в&amp;низ</translation>
    </message>
    <message>
        <source>&amp;Step up</source>
        <translation>Шаг вв&amp;ерх</translation>
    </message>
    <message>
        <source>&amp;Select All</source>
        <translation>&amp;Выделить всё</translation>
    </message>
</context>
<context>
    <name>QDockWidget</name>
    <message>
        <source>Close</source>
        <translation>Закрыть</translation>
    </message>
    <message>
        <source>Float</source>
        <translation>Открепить</translation>
    </message>
    <message>
        <source>Undocks and re-attaches the dock widget</source>
        <translation>Открепляет панель и прикрепляет её обратно</translation>
    </message>
    <message>
        <source>Closes the dock widget</source>
        <translation>Закрывает панель</translation>
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
        <translation>Файл</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Открыть</translation>
    </message>
    <message>
        <source>&amp;Open</source>
        <translation>&amp;Открыть</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Сохранить</translation>
    </message>
    <message>
        <source>Alias</source>
        <translation>Псевдоним</translation>
    </message>
    <message>
        <source>Drive</source>
        <translation>Диск</translation>
    </message>
    <message>
        <source>Files</source>
        <translation>Файлы</translation>
    </message>
    <message>
        <source>Show </source>
        <translation>Показать </translation>
    </message>
    <message>
        <source>&apos;%1&apos; is write protected.
Do you want to delete it anyway?</source>
        <translation>«%1» защищён от записи.
Всё равно удалить?</translation>
    </message>
    <message>
        <source>Are you sure you want to delete &apos;%1&apos;?</source>
        <translation>Удалить «%1»?</translation>
    </message>
    <message>
        <source>List of places and bookmarks</source>
        <translation>Места и закладки</translation>
    </message>
    <message>
        <source>File &amp;name:</source>
        <translation>&amp;Имя файла:</translation>
    </message>
    <message>
        <source>File Folder</source>
        <translation>Папка</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Удалить</translation>
    </message>
    <message>
        <source>New Folder</source>
        <translation>Новая папка</translation>
    </message>
    <message>
        <source>Folder</source>
        <translation>Папка</translation>
    </message>
    <message>
        <source>Parent Directory</source>
        <translation>Родительская папка</translation>
    </message>
    <message>
        <source>&amp;New Folder</source>
        <translation>&amp;Новая папка</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Убрать</translation>
    </message>
    <message>
        <source>My Computer</source>
        <translation>Мой компьютер</translation>
    </message>
    <message>
        <source>Look in:</source>
        <translation>Папка:</translation>
    </message>
    <message>
        <source>Create a New Folder</source>
        <translation>Создать новую папку</translation>
    </message>
    <message>
        <source>%1 File</source>
        <translation>Файл %1</translation>
    </message>
    <message>
        <source>Files of type:</source>
        <translation>Тип файлов:</translation>
    </message>
    <message>
        <source>Find Directory</source>
        <translation>Выбор папки</translation>
    </message>
    <message>
        <source>Show &amp;hidden files</source>
        <translation>Показывать &amp;скрытые файлы</translation>
    </message>
    <message>
        <source>Save As</source>
        <translation>Сохранить как</translation>
    </message>
    <message>
        <source>%1
Directory not found.
Please verify the correct directory name was given.</source>
        <translation>%1
Папка не найдена.
Проверьте, правильно ли указано её имя.</translation>
    </message>
    <message>
        <source>Sidebar</source>
        <translation>Боковая панель</translation>
    </message>
    <message>
        <source>List View</source>
        <translation>Список</translation>
    </message>
    <message>
        <source>&amp;Choose</source>
        <translation>&amp;Выбрать</translation>
    </message>
    <message>
        <source>&amp;Delete</source>
        <translation>&amp;Удалить</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Все файлы (*)</translation>
    </message>
    <message>
        <source>All Files (*)</source>
        <translation>Все файлы (*)</translation>
    </message>
    <message>
        <source>Directories</source>
        <translation>Папки</translation>
    </message>
    <message>
        <source>&amp;Rename</source>
        <translation>&amp;Переименовать</translation>
    </message>
    <message>
        <source>Could not delete directory.</source>
        <translation>Не удалось удалить папку.</translation>
    </message>
    <message>
        <source>Directory:</source>
        <translation>Папка:</translation>
    </message>
    <message>
        <source>Unknown</source>
        <translation>Неизвестно</translation>
    </message>
    <message>
        <source>%1 already exists.
Do you want to replace it?</source>
        <translation>%1 уже существует.
Заменить?</translation>
    </message>
    <message>
        <source>Forward</source>
        <translation>Вперёд</translation>
    </message>
    <message>
        <source>Go forward</source>
        <translation>Перейти вперёд</translation>
    </message>
    <message>
        <source>Go to the parent directory</source>
        <translation>Перейти в родительскую папку</translation>
    </message>
    <message>
        <source>Recent Places</source>
        <translation>Недавние места</translation>
    </message>
    <message>
        <source>Go back</source>
        <translation>Перейти назад</translation>
    </message>
    <message>
        <source>Change to detail view mode</source>
        <translation>Подробный вид</translation>
    </message>
    <message>
        <source>Create New Folder</source>
        <translation>Создать папку</translation>
    </message>
    <message>
        <source>Shortcut</source>
        <translation>Ярлык</translation>
    </message>
    <message>
        <source>Detail View</source>
        <translation>Подробный вид</translation>
    </message>
    <message>
        <source>%1
File not found.
Please verify the correct file name was given.</source>
        <translation>%1
Файл не найден.
Проверьте, правильно ли указано его имя.</translation>
    </message>
    <message>
        <source>Change to list view mode</source>
        <translation>Вид списка</translation>
    </message>
</context>
<context>
    <name>QFileSystemModel</name>
    <message>
        <source>Kind</source>
        <translation>Вид</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Имя</translation>
    </message>
    <message>
        <source>Size</source>
        <translation>Размер</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>Тип</translation>
    </message>
    <message>
        <source>My Computer</source>
        <translation>Мой компьютер</translation>
    </message>
    <message>
        <source>Computer</source>
        <translation>Компьютер</translation>
    </message>
    <message>
        <source>Invalid filename</source>
        <translation>Недопустимое имя файла</translation>
    </message>
    <message>
        <source>&lt;b&gt;The name &quot;%1&quot; cannot be used.&lt;/b&gt;&lt;p&gt;Try using another name, with fewer characters or no punctuation marks.</source>
        <translation>&lt;b&gt;Имя «%1» использовать нельзя.&lt;/b&gt;&lt;p&gt;Попробуйте другое имя, короче или без знаков препинания.</translation>
    </message>
    <message>
        <source>Date Modified</source>
        <translation>Изменён</translation>
    </message>
</context>
<context>
    <name>QGnomeTheme</name>
    <message>
        <source>&amp;OK</source>
        <translation>&amp;OK</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Сохранить</translation>
    </message>
    <message>
        <source>&amp;Close</source>
        <translation>&amp;Закрыть</translation>
    </message>
    <message>
        <source>Close without Saving</source>
        <translation>Закрыть без сохранения</translation>
    </message>
    <message>
        <source>&amp;Cancel</source>
        <translation>&amp;Отмена</translation>
    </message>
</context>
<context>
    <name>QLineEdit</name>
    <message>
        <source>Cu&amp;t</source>
        <translation>Выре&amp;зать</translation>
    </message>
    <message>
        <source>&amp;Copy</source>
        <translation>&amp;Копировать</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Повторить</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Отменить</translation>
    </message>
    <message>
        <source>&amp;Paste</source>
        <translation>&amp;Вставить</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Удалить</translation>
    </message>
    <message>
        <source>Select All</source>
        <translation>Выделить всё</translation>
    </message>
</context>
<context>
    <name>QPlatformTheme</name>
    <message>
        <source>OK</source>
        <translation>ОК</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Сохранить</translation>
    </message>
    <message>
        <source>Save All</source>
        <translation>Сохранить все</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Открыть</translation>
    </message>
    <message>
        <source>&amp;Yes</source>
        <translation>&amp;Да</translation>
    </message>
    <message>
        <source>Yes to &amp;All</source>
        <translation>Да для &amp;всех</translation>
    </message>
    <message>
        <source>&amp;No</source>
        <translation>&amp;Нет</translation>
    </message>
    <message>
        <source>N&amp;o to All</source>
        <translation>Н&amp;ет для всех</translation>
    </message>
    <message>
        <source>Abort</source>
        <translation>Прервать</translation>
    </message>
    <message>
        <source>Retry</source>
        <translation>Повторить</translation>
    </message>
    <message>
        <source>Ignore</source>
        <translation>Пропустить</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Закрыть</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Отмена</translation>
    </message>
    <message>
        <source>Discard</source>
        <translation>Не сохранять</translation>
    </message>
    <message>
        <source>Help</source>
        <translation>Справка</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Применить</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Сбросить</translation>
    </message>
    <message>
        <source>Restore Defaults</source>
        <translation>Восстановить значения по умолчанию</translation>
    </message>
</context>
<context>
    <name>QScrollBar</name>
    <message>
        <source>Top</source>
        <translation>В начало</translation>
    </message>
    <message>
        <source>Scroll down</source>
        <translation>Прокрутить вниз</translation>
    </message>
    <message>
        <source>Scroll here</source>
        <translation>Прокрутить сюда</translation>
    </message>
    <message>
        <source>Scroll left</source>
        <translation>Прокрутить влево</translation>
    </message>
    <message>
        <source>Bottom</source>
        <translation>В конец</translation>
    </message>
    <message>
        <source>Page up</source>
        <translation>На страницу вверх</translation>
    </message>
    <message>
        <source>Page right</source>
        <translation>На страницу вправо</translation>
    </message>
    <message>
        <source>Scroll up</source>
        <translation>Прокрутить вверх</translation>
    </message>
    <message>
        <source>Scroll right</source>
        <translation>Прокрутить вправо</translation>
    </message>
    <message>
        <source>Left edge</source>
        <translation>К левому краю</translation>
    </message>
    <message>
        <source>Page down</source>
        <translation>На страницу вниз</translation>
    </message>
    <message>
        <source>Page left</source>
        <translation>На страницу влево</translation>
    </message>
    <message>
        <source>Right edge</source>
        <translation>К правому краю</translation>
    </message>
</context>
<context>
    <name>QTabBar</name>
    <message>
        <source>Scroll Left</source>
        <translation>Прокрутить влево</translation>
    </message>
    <message>
        <source>Scroll Right</source>
        <translation>Прокрутить вправо</translation>
    </message>
</context>
<context>
    <name>QWidgetTextControl</name>
    <message>
        <source>Cu&amp;t</source>
        <translation>Выре&amp;зать</translation>
    </message>
    <message>
        <source>&amp;Copy</source>
        <translation>&amp;Копировать</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Повторить</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Отменить</translation>
    </message>
    <message>
        <source>&amp;Paste</source>
        <translation>&amp;Вставить</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Удалить</translation>
    </message>
    <message>
        <source>Select All</source>
        <translation>Выделить всё</translation>
    </message>
    <message>
        <source>Copy &amp;Link Location</source>
        <translation>Копировать &amp;адрес ссылки</translation>
    </message>
</context>
<context>
    <name>Sheet</name>
    <message>
        <source>frame</source>
        <translation>стойка</translation>
    </message>
    <message>
        <source>crank</source>
        <translation>кривошип</translation>
    </message>
    <message>
        <source>coupler</source>
        <translation>шатун</translation>
    </message>
    <message>
        <source>link</source>
        <translation>звено</translation>
    </message>
    <message>
        <source>rod</source>
        <translation>тяга</translation>
    </message>
    <message>
        <source>platform</source>
        <translation>платформа</translation>
    </message>
    <message>
        <source>Design parameters</source>
        <translation>Параметры конструкции</translation>
    </message>
    <message>
        <source> (derived)</source>
        <translation> (производная величина)</translation>
    </message>
    <message>
        <source>Derived dimensions</source>
        <translation>Производные размеры</translation>
    </message>
    <message>
        <source>Links and guides (between joint centres)</source>
        <translation>Звенья и направляющие (между центрами шарниров)</translation>
    </message>
    <message>
        <source>between</source>
        <translation>между</translation>
    </message>
    <message>
        <source>part</source>
        <translation>деталь</translation>
    </message>
    <message>
        <source>kind</source>
        <translation>вид</translation>
    </message>
    <message>
        <source>length</source>
        <translation>длина</translation>
    </message>
    <message>
        <source>guide</source>
        <translation>направляющая</translation>
    </message>
    <message>
        <source>guide (stroke)</source>
        <translation>направляющая (ход)</translation>
    </message>
    <message>
        <source>Ranges of motion</source>
        <translation>Диапазоны движения</translation>
    </message>
    <message>
        <source>variable</source>
        <translation>переменная</translation>
    </message>
    <message>
        <source>role</source>
        <translation>роль</translation>
    </message>
    <message>
        <source>this pose</source>
        <translation>это положение</translation>
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
        <translation>ед. изм.</translation>
    </message>
    <message>
        <source>input (actuated)</source>
        <translation>вход (приводной)</translation>
    </message>
    <message>
        <source>output</source>
        <translation>выход</translation>
    </message>
    <message>
        <source>pose</source>
        <translation>положение</translation>
    </message>
    <message>
        <source>home</source>
        <translation>исходное положение</translation>
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
        <translation>Каждый приводной вход на концах своего диапазона при остальных входах в исходном положении — там, где механизм достигает такого положения.</translation>
    </message>
    <message>
        <source>No singular pose in the range of motion</source>
        <translation>Нет особых положений в диапазоне движения</translation>
    </message>
    <message>
        <source>singularity margin ≥ %1</source>
        <translation>запас до особого положения ≥ %1</translation>
    </message>
    <message>
        <source>least at %1 = %2</source>
        <translation>наименьший при %1 = %2</translation>
    </message>
    <message>
        <source>%1 over %2</source>
        <translation>%1 в зависимости от %2</translation>
    </message>
    <message>
        <source>Dimensioned drawing</source>
        <translation>Чертёж с размерами</translation>
    </message>
    <message>
        <source>The mechanism in the pose of this sheet, scale %1</source>
        <translation>Механизм в положении этого листа, масштаб %1</translation>
    </message>
    <message>
        <source>Pose: %1. Scale %2 on A4 (the scale bar holds on any print size). Lengths in mm, angles in degrees; the dimensions are those of the pose shown.</source>
        <translation>Положение: %1. Масштаб %2 на листе A4 (масштабная линейка верна при любом размере печати). Длины в мм, углы в градусах; размеры даны для показанного положения.</translation>
    </message>
    <message>
        <source>Design warnings</source>
        <translation>Предупреждения по конструкции</translation>
    </message>
    <message>
        <source>Key poses</source>
        <translation>Характерные положения</translation>
    </message>
    <message>
        <source>Checks</source>
        <translation>Проверки</translation>
    </message>
    <message>
        <source>Plots</source>
        <translation>Графики</translation>
    </message>
    <message>
        <source>screw beyond the motor body at d_min</source>
        <translation>выступание винта за корпус двигателя при d_min</translation>
    </message>
    <message>
        <source>screw beyond the motor body at d_max (least free screw length)</source>
        <translation>выступание винта за корпус двигателя при d_max (наименьшая свободная длина винта)</translation>
    </message>
    <message>
        <source>motor steps per revolution of the screw</source>
        <translation>шагов двигателя на один оборот винта</translation>
    </message>
    <message>
        <source>motor speed at ḋ_max, 60·ḋ_max/h</source>
        <translation>частота вращения двигателя при ḋ_max, 60·ḋ_max/h</translation>
    </message>
    <message>
        <source>step rate at ḋ_max, ḋ_max/Δd</source>
        <translation>частота шагов при ḋ_max, ḋ_max/Δd</translation>
    </message>
    <message>
        <source>Key poses over the range and the recommended range</source>
        <translation>Характерные положения: диапазон движения и рекомендуемый диапазон</translation>
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
        <translation> (данное положение)</translation>
    </message>
    <message>
        <source>T at F_max = %1 N, θ̇ at ḋ_max = %2 mm/s, Δθ per motor step Δd = %3 mm. The recommended range keeps J — and with it T, θ̇ and Δθ — within %4 % of its best over the range (the document: θ = −60°…40°).</source>
        <translation>T при F_max = %1 Н, θ̇ при ḋ_max = %2 мм/с, Δθ на один шаг двигателя Δd = %3 мм. В рекомендуемом диапазоне J — а вместе с ним T, θ̇ и Δθ — остаётся в пределах %4 % от своего наилучшего значения в диапазоне (в документе: θ = −60°…40°).</translation>
    </message>
    <message>
        <source>Actuator check</source>
        <translation>Проверка привода</translation>
    </message>
    <message>
        <source>The chosen motor: lead h = %1 mm, step Δd = %2 mm, ḋ_max = %3 mm/s, thrust F_max = %4 N, screw efficiency η = %5; body %6 mm long.</source>
        <translation>Выбранный двигатель: ход винта h = %1 мм, шаг Δd = %2 мм, ḋ_max = %3 мм/с, осевое усилие F_max = %4 Н, КПД винта η = %5; длина корпуса %6 мм.</translation>
    </message>
    <message>
        <source>Motor body fits the shortest diagonal</source>
        <translation>Корпус двигателя короче наименьшей диагонали</translation>
    </message>
    <message>
        <source>stroke d_max − d_min = %1 mm</source>
        <translation>ход d_max − d_min = %1 мм</translation>
    </message>
    <message>
        <source>worst at θ = %1, best at θ = %2; recommended range %3…%4</source>
        <translation>худшее при θ = %1, лучшее при θ = %2; рекомендуемый диапазон %3…%4</translation>
    </message>
    <message>
        <source>Output torque T = J·F_max (13)</source>
        <translation>Выходной момент T = J·F_max (13)</translation>
    </message>
    <message>
        <source>least T ≥ %1 % of the best</source>
        <translation>наименьший T ≥ %1 % от наибольшего</translation>
    </message>
    <message>
        <source>Output speed θ̇ = ḋ_max/J (8)</source>
        <translation>Выходная скорость θ̇ = ḋ_max/J (8)</translation>
    </message>
    <message>
        <source>greatest θ̇ ≤ the least ÷ %1</source>
        <translation>наибольшая θ̇ ≤ наименьшая ÷ %1</translation>
    </message>
    <message>
        <source>Output resolution Δθ = Δd/J</source>
        <translation>Разрешение на выходе Δθ = Δd/J</translation>
    </message>
    <message>
        <source>coarsest Δθ ≤ the finest ÷ %1</source>
        <translation>самое грубое Δθ ≤ самое мелкое ÷ %1</translation>
    </message>
    <message>
        <source>No singular pose in the range (θ = ±90°)</source>
        <translation>Нет особых положений в диапазоне (θ = ±90°)</translation>
    </message>
    <message>
        <source>|cos θ| ≥ %1</source>
        <translation>|cos θ| ≥ %1</translation>
    </message>
    <message>
        <source>Motor torque to push F_max</source>
        <translation>Момент двигателя для создания усилия F_max</translation>
    </message>
    <message>
        <source>the motor must give it at %1 min⁻¹ (%2 steps/s)</source>
        <translation>двигатель должен развивать его при %1 мин⁻¹ (%2 шаг/с)</translation>
    </message>
    <message>
        <source>FAIL above means that the range of θ reaches where J falls steeply: keep the joint in the recommended range %1…%2 where it must give its torque, speed and resolution.</source>
        <translation>«НЕ ВЫПОЛНЕНО» выше означает, что диапазон θ заходит в область резкого спада J: там, где шарнир должен обеспечивать свой момент, скорость и разрешение, держите его в рекомендуемом диапазоне %1…%2.</translation>
    </message>
    <message>
        <source>Diagonal length d(θ) (2), fig. 8</source>
        <translation>Длина диагонали d(θ) (2), рис. 8</translation>
    </message>
    <message>
        <source>Transmission angle μ(θ), fig. 10</source>
        <translation>Угол передачи μ(θ), рис. 10</translation>
    </message>
    <message>
        <source>Jacobian J(θ) = ∂d/∂θ (7), fig. 11</source>
        <translation>Якобиан J(θ) = ∂d/∂θ (7), рис. 11</translation>
    </message>
    <message>
        <source>Output torque T = J·F_max (13), fig. 17</source>
        <translation>Выходной момент T = J·F_max (13), рис. 17</translation>
    </message>
    <message>
        <source>Output speed θ̇ = ḋ_max/J, fig. 16</source>
        <translation>Выходная скорость θ̇ = ḋ_max/J, рис. 16</translation>
    </message>
    <message>
        <source>Output resolution Δθ = Δd/J, fig. 15</source>
        <translation>Разрешение на выходе Δθ = Δd/J, рис. 15</translation>
    </message>
    <message>
        <source>θ (°)</source>
        <translation>θ (°)</translation>
    </message>
    <message>
        <source>beyond the θ range</source>
        <translation>за пределами диапазона θ</translation>
    </message>
    <message>
        <source>this design (k = %1)</source>
        <translation>эта конструкция (k = %1)</translation>
    </message>
    <message>
        <source>recommended range</source>
        <translation>рекомендуемый диапазон</translation>
    </message>
    <message>
        <source>steep region</source>
        <translation>крутой участок</translation>
    </message>
    <message>
        <source>a = %1 mm; the family k = 0.3 … 1.5 at the same a</source>
        <translation>a = %1 мм; семейство k = 0,3 … 1,5 при том же a</translation>
    </message>
    <message>
        <source>crank-rocker</source>
        <translation>кривошипно-коромысловый</translation>
    </message>
    <message>
        <source>rocker-crank</source>
        <translation>коромыслово-кривошипный</translation>
    </message>
    <message>
        <source>double-crank</source>
        <translation>двухкривошипный</translation>
    </message>
    <message>
        <source>double-rocker</source>
        <translation>двухкоромысловый</translation>
    </message>
    <message>
        <source>triple-rocker (non-Grashof)</source>
        <translation>трёхкоромысловый (не по Грасгофу)</translation>
    </message>
    <message>
        <source>change-point</source>
        <translation>переходный</translation>
    </message>
    <message>
        <source>class</source>
        <translation>класс</translation>
    </message>
    <message>
        <source>Grashof class, s + l against p + q</source>
        <translation>класс по Грасгофу: s + l в сравнении с p + q</translation>
    </message>
    <message>
        <source>shortest + longest link</source>
        <translation>самое короткое + самое длинное звено</translation>
    </message>
    <message>
        <source>the other two links</source>
        <translation>два остальных звена</translation>
    </message>
    <message>
        <source>Key poses over the crank angle</source>
        <translation>Характерные положения по углу кривошипа</translation>
    </message>
    <message>
        <source>least μ</source>
        <translation>наименьший μ</translation>
    </message>
    <message>
        <source>At the constant crank speed ω₁ = %1 rad/s.</source>
        <translation>При постоянной угловой скорости кривошипа ω₁ = %1 рад/с.</translation>
    </message>
    <message>
        <source>Design check</source>
        <translation>Проверка конструкции</translation>
    </message>
    <message>
        <source>Grashof class</source>
        <translation>Класс по Грасгофу</translation>
    </message>
    <message>
        <source>s + l = %1 mm, p + q = %2 mm</source>
        <translation>s + l = %1 мм; p + q = %2 мм</translation>
    </message>
    <message>
        <source>Crank angle range</source>
        <translation>Диапазон угла кривошипа</translation>
    </message>
    <message>
        <source>the crank AB turns fully</source>
        <translation>кривошип AB проворачивается полностью</translation>
    </message>
    <message>
        <source>the crank AB cannot turn fully</source>
        <translation>кривошип AB не проворачивается полностью</translation>
    </message>
    <message>
        <source>Least transmission angle over the range</source>
        <translation>Наименьший угол передачи в диапазоне</translation>
    </message>
    <message>
        <source>at α = %1°</source>
        <translation>при α = %1°</translation>
    </message>
    <message>
        <source>Rocker angle δ(α)</source>
        <translation>Угол коромысла δ(α)</translation>
    </message>
    <message>
        <source>Transmission angle μ(α)</source>
        <translation>Угол передачи μ(α)</translation>
    </message>
    <message>
        <source>Rocker angular velocity ω₃(α)</source>
        <translation>Угловая скорость коромысла ω₃(α)</translation>
    </message>
    <message>
        <source>Rocker angular acceleration ε₃(α)</source>
        <translation>Угловое ускорение коромысла ε₃(α)</translation>
    </message>
    <message>
        <source>μ = %1°: poor below</source>
        <translation>μ = %1°: ниже — плохая передача</translation>
    </message>
    <message>
        <source>none</source>
        <translation>нет</translation>
    </message>
    <message>
        <source>inverse</source>
        <translation>обратное</translation>
    </message>
    <message>
        <source>direct</source>
        <translation>прямое</translation>
    </message>
    <message>
        <source>combined</source>
        <translation>комбинированное</translation>
    </message>
    <message>
        <source>PASS</source>
        <translation>ВЫПОЛНЕНО</translation>
    </message>
    <message>
        <source>FAIL</source>
        <translation>НЕ ВЫПОЛНЕНО</translation>
    </message>
    <message>
        <source>INFO</source>
        <translation>СПРАВКА</translation>
    </message>
    <message>
        <source>singularity</source>
        <translation>сингулярность</translation>
    </message>
    <message>
        <source>singularity class of the pose</source>
        <translation>вид сингулярности в этом положении</translation>
    </message>
    <message>
        <source>PKM Studio · Parameter sheet</source>
        <translation>PKM Studio · Лист параметров</translation>
    </message>
    <message>
        <source>page %1 of %2</source>
        <translation>стр. %1 из %2</translation>
    </message>
    <message>
        <source>Parameter sheet</source>
        <translation>Лист параметров</translation>
    </message>
    <message>
        <source>field</source>
        <translation>поле</translation>
    </message>
    <message>
        <source>value</source>
        <translation>значение</translation>
    </message>
    <message>
        <source>Design</source>
        <translation>Конструкция</translation>
    </message>
    <message>
        <source>Mechanism</source>
        <translation>Механизм</translation>
    </message>
    <message>
        <source>Pose</source>
        <translation>Положение</translation>
    </message>
    <message>
        <source>Date</source>
        <translation>Дата</translation>
    </message>
    <message>
        <source>Software</source>
        <translation>Программа</translation>
    </message>
    <message>
        <source>About</source>
        <translation>Описание</translation>
    </message>
    <message>
        <source>Units: lengths mm, angles degrees, forces N, torques N·m, times s, unless a column says otherwise.</source>
        <translation>Единицы: длины — мм, углы — градусы, силы — Н, моменты — Н·м, время — с, если в столбце не указано иное.</translation>
    </message>
    <message>
        <source>Geometry</source>
        <translation>Геометрия</translation>
    </message>
    <message>
        <source>Range of motion</source>
        <translation>Диапазон движения</translation>
    </message>
    <message>
        <source>Actuator</source>
        <translation>Привод</translation>
    </message>
    <message>
        <source>Drawing only</source>
        <translation>Только для чертежа</translation>
    </message>
    <message>
        <source>Working and assembly modes</source>
        <translation>Рабочие режимы и варианты сборки</translation>
    </message>
    <message>
        <source>symbol</source>
        <translation>обозначение</translation>
    </message>
    <message>
        <source>quantity</source>
        <translation>величина</translation>
    </message>
    <message>
        <source>key</source>
        <translation>ключ</translation>
    </message>
    <message>
        <source>check</source>
        <translation>проверка</translation>
    </message>
    <message>
        <source>limit</source>
        <translation>предел</translation>
    </message>
    <message>
        <source>result</source>
        <translation>результат</translation>
    </message>
    <message>
        <source>x (mm)</source>
        <translation>x (мм)</translation>
    </message>
    <message>
        <source>y (mm)</source>
        <translation>y (мм)</translation>
    </message>
    <message>
        <source>scale (A4)</source>
        <translation>масштаб (A4)</translation>
    </message>
    <message>
        <source>scale bar</source>
        <translation>масштабная линейка</translation>
    </message>
    <message>
        <source>units</source>
        <translation>единицы</translation>
    </message>
    <message>
        <source>mm, degrees</source>
        <translation>мм, градусы</translation>
    </message>
    <message>
        <source>design</source>
        <translation>конструкция</translation>
    </message>
    <message>
        <source>date</source>
        <translation>дата</translation>
    </message>
    <message>
        <source>Parameter sheet: %1</source>
        <translation>Лист параметров: %1</translation>
    </message>
    <message>
        <source>Workspace</source>
        <translation>Рабочее пространство</translation>
    </message>
    <message>
        <source>The platform positions reachable with every actuated input inside its range%1, on a grid of %2 × %3 square cells of %4 mm (as &apos;pkm workspace --grid %5&apos;).</source>
        <translation>Положения платформы, достижимые при каждом приводном входе в пределах его диапазона%1, на сетке %2 × %3 квадратных ячеек со стороной %4 мм (как &apos;pkm workspace --grid %5&apos;).</translation>
    </message>
    <message>
        <source>area of this form&apos;s workspace (exact)</source>
        <translation>площадь рабочего пространства этой формы (точно)</translation>
    </message>
    <message>
        <source>area of the extended (O) form (exact)</source>
        <translation>площадь для вытянутой (O) формы (точно)</translation>
    </message>
    <message>
        <source>area of the crossed (X) form (exact)</source>
        <translation>площадь для скрещенной (X) формы (точно)</translation>
    </message>
    <message>
        <source>area of this form on the grid</source>
        <translation>площадь этой формы по сетке</translation>
    </message>
    <message>
        <source>area of the workspace (grid)</source>
        <translation>площадь рабочего пространства (по сетке)</translation>
    </message>
    <message>
        <source>area in mode %1 (grid)</source>
        <translation>площадь в режиме %1 (по сетке)</translation>
    </message>
    <message>
        <source>area of the union of all modes (grid)</source>
        <translation>площадь объединения всех режимов (по сетке)</translation>
    </message>
    <message>
        <source>travel of the carrying axis</source>
        <translation>ход несущей оси</translation>
    </message>
    <message>
        <source>volume: the area extruded over the travel</source>
        <translation>объём: площадь, вытянутая на длину хода</translation>
    </message>
    <message>
        <source>reachable cells from x</source>
        <translation>достижимые ячейки от x</translation>
    </message>
    <message>
        <source>reachable cells to x</source>
        <translation>достижимые ячейки до x</translation>
    </message>
    <message>
        <source>reachable cells from y</source>
        <translation>достижимые ячейки от y</translation>
    </message>
    <message>
        <source>reachable cells to y</source>
        <translation>достижимые ячейки до y</translation>
    </message>
    <message>
        <source>cells</source>
        <translation>ячейки</translation>
    </message>
    <message>
        <source>reachable cells of the grid</source>
        <translation>достижимые ячейки сетки</translation>
    </message>
    <message>
        <source>Area per working and assembly mode</source>
        <translation>Площадь для каждого рабочего режима и варианта сборки</translation>
    </message>
    <message>
        <source>mode</source>
        <translation>режим</translation>
    </message>
    <message>
        <source>area (grid)</source>
        <translation>площадь (по сетке)</translation>
    </message>
    <message>
        <source>area (exact)</source>
        <translation>площадь (точно)</translation>
    </message>
    <message>
        <source>note</source>
        <translation>примечание</translation>
    </message>
    <message>
        <source>this design</source>
        <translation>данная конструкция</translation>
    </message>
    <message>
        <source>no workspace</source>
        <translation>нет рабочего пространства</translation>
    </message>
    <message>
        <source>Workspaces of the modes</source>
        <translation>Рабочие пространства режимов</translation>
    </message>
    <message>
        <source>As &apos;pkm workspace -o FILE.png&apos;: this design&apos;s mode dark blue over the others&apos; light blue, the outline of their union dark.</source>
        <translation>Как в &apos;pkm workspace -o FILE.png&apos;: режим данной конструкции — тёмно-синим поверх остальных (голубым), контур их объединения — тёмным.</translation>
    </message>
    <message>
        <source>As &apos;pkm workspace -o FILE.png&apos;: the reachable cells light blue with a dark outline.</source>
        <translation>Как в &apos;pkm workspace -o FILE.png&apos;: достижимые ячейки — голубым, с тёмным контуром.</translation>
    </message>
    <message>
        <source>Singularity map: det J</source>
        <translation>Карта сингулярностей: det J</translation>
    </message>
    <message>
        <source>As &apos;pkm map -o FILE.png&apos;: det J blue below 0, white at 0 (a direct singularity), red above 0, clipped at ±%1; the inverse singular curves dark red, the direct ones dashed.</source>
        <translation>Как в &apos;pkm map -o FILE.png&apos;: det J синим ниже 0, белым при 0 (прямая сингулярность), красным выше 0, с ограничением ±%1; обратные кривые особых положений тёмно-красные, прямые — штриховые.</translation>
    </message>
    <message>
        <source>Singular poses in the workspace</source>
        <translation>Особые положения в рабочем пространстве</translation>
    </message>
    <message>
        <source>near-singular cells (margin &lt; %1, about 3° from a singular pose)</source>
        <translation>ячейки вблизи особых положений (запас &lt; %1, примерно 3° от особого положения)</translation>
    </message>
    <message>
        <source>their area</source>
        <translation>их площадь</translation>
    </message>
    <message>
        <source>Singular curves, each with one of its poses</source>
        <translation>Кривые особых положений, для каждой — одно из её положений</translation>
    </message>
    <message>
        <source>where</source>
        <translation>где</translation>
    </message>
    <message>
        <source>type</source>
        <translation>тип</translation>
    </message>
    <message>
        <source>curve length</source>
        <translation>длина кривой</translation>
    </message>
    <message>
        <source>Inverse: a leg loses a degree of freedom (a link perpendicular to its guide); direct: the platform gains one (the links in line). The pose given is the middle of each curve.</source>
        <translation>Обратная: кинематическая цепь теряет степень свободы (звено перпендикулярно своей направляющей); прямая: платформа приобретает лишнюю степень свободы (звенья на одной прямой). Приведённое положение — середина каждой кривой.</translation>
    </message>
    <message>
        <source>No singular curve lies inside the workspace.</source>
        <translation>Внутри рабочего пространства нет кривых особых положений.</translation>
    </message>
    <message>
        <source>Stroke of %1 the workspace uses</source>
        <translation>Ход %1, используемый рабочим пространством</translation>
    </message>
    <message>
        <source>within the guide %1 … %2</source>
        <translation>в пределах направляющей %1 … %2</translation>
    </message>
    <message>
        <source>within its range %1 … %2</source>
        <translation>в пределах своего диапазона %1 … %2</translation>
    </message>
    <message>
        <source>used from %1 to %2</source>
        <translation>используется от %1 до %2</translation>
    </message>
    <message>
        <source>Direct singular poses in the workspace</source>
        <translation>Прямые особые положения в рабочем пространстве</translation>
    </message>
    <message>
        <source>Inverse singular poses in the workspace</source>
        <translation>Обратные особые положения в рабочем пространстве</translation>
    </message>
    <message>
        <source>none: the platform would move with the actuators locked</source>
        <translation>не допускаются: платформа двигалась бы при застопоренных приводах</translation>
    </message>
    <message>
        <source>where a leg reaches the end of its reach; keep away in use</source>
        <translation>где кинематическая цепь достигает предела досягаемости; в работе держаться в стороне</translation>
    </message>
    <message>
        <source>no singular curve of this kind</source>
        <translation>нет кривых особых положений этого вида</translation>
    </message>
    <message>
        <source>α ∈ [%1°, %2°]</source>
        <translation>α ∈ [%1°; %2°]</translation>
    </message>
    <message>
        <source>min⁻¹</source>
        <translation>мин⁻¹</translation>
    </message>
    <message>
        <source>steps/s</source>
        <translation>шаг/с</translation>
    </message>
    <message>
        <source>mm³</source>
        <translation>мм³</translation>
    </message>
    <message>
        <source>Actuator capability</source>
        <translation>Возможности приводов</translation>
    </message>
    <message>
        <source>What the actuators deliver at the platform at this pose, every actuator within its limits: the force and the speed in the weakest and the strongest direction, the error from half a step per actuator and the stiffness from the actuators alone.</source>
        <translation>Что приводы дают на платформе в этом положении, каждый в своих пределах: сила и скорость в самом слабом и самом сильном направлении, погрешность от полушага каждого привода и жёсткость от одних приводов.</translation>
    </message>
    <message>
        <source>The actuator&apos;s axial stiffness is an assumed value (about 20 N/µm for a small lead screw with its nut and bearings): Table 1 gives none.</source>
        <translation>Осевая жёсткость привода принята (около 20 Н/мкм для небольшого ходового винта с гайкой и подшипниками): в таблице 1 её нет.</translation>
    </message>
    <message>
        <source>Actuator values left at their defaults are assumed, plausible ones (a NEMA 17 stepper with a 5:1 gearbox, a small lead-screw slide): the source documents give none.</source>
        <translation>Параметры приводов, оставленные по умолчанию, приняты правдоподобными (шаговый двигатель NEMA 17 с редуктором 5:1, небольшой модуль с ходовым винтом): в исходных документах их нет.</translation>
    </message>
    <message>
        <source>The actuator alone would make the joint %1 N·m/rad stiff here; the measured %2 N·m/rad is lower because the hinges, links and frame yield in series with it (1/K = 1/K_actuator + 1/K_rest): together they are about %3 N·m/rad.</source>
        <translation>Один привод дал бы здесь шарниру жёсткость %1 Н·м/рад; измеренная %2 Н·м/рад ниже, потому что шарниры, звенья и рама податливы последовательно с ним (1/K = 1/K_привода + 1/K_остального): вместе они дают около %3 Н·м/рад.</translation>
    </message>
    <message>
        <source>The actuator alone gives %1 N·m/rad here, less than the measured %2 N·m/rad of the whole joint: the assumed axial stiffness of the actuator is too low for the measurement, or the pose is near a singularity where the actuator cannot hold the output.</source>
        <translation>Один привод даёт здесь %1 Н·м/рад, меньше измеренных %2 Н·м/рад всего шарнира: принятая осевая жёсткость привода слишком мала для измерения, или положение близко к особому, где привод не удерживает выходное звено.</translation>
    </message>
    <message>
        <source>The actuators hold the design&apos;s load at this pose</source>
        <translation>Приводы удерживают нагрузку конструкции в этом положении</translation>
    </message>
    <message>
        <source>max |τ_i| / τ_max,i ≤ 1</source>
        <translation>max |τ_i| / τ_max,i ≤ 1</translation>
    </message>
    <message>
        <source>no load</source>
        <translation>нет нагрузки</translation>
    </message>
    <message>
        <source>The design states no load (load_x, load_y, load_moment or load_torque in the actuator group).</source>
        <translation>В конструкции не задана нагрузка (load_x, load_y, load_moment или load_torque в группе приводов).</translation>
    </message>
    <message>
        <source>actuator %1 at %2 % of its limit</source>
        <translation>привод %1 на %2 % своего предела</translation>
    </message>
    <message>
        <source>at a direct singularity no effort of the actuators holds a load</source>
        <translation>в особом положении прямой кинематики никакое усилие приводов не удерживает нагрузку</translation>
    </message>
    <message>
        <source>Required at this pose: %1</source>
        <translation>Требуется в этом положении: %1</translation>
    </message>
    <message>
        <source>undefined</source>
        <translation>не определено</translation>
    </message>
    <message>
        <source>Every requirement holds over the whole workspace</source>
        <translation>Все требования выполняются во всём рабочем пространстве</translation>
    </message>
    <message>
        <source>area met = workspace area</source>
        <translation>площадь выполнения = площадь рабочего пространства</translation>
    </message>
    <message>
        <source>met in %1 mm² of %2 mm² (grid of %3 × %4 cells)</source>
        <translation>выполняются на %1 мм² из %2 мм² (сетка %3 × %4 ячеек)</translation>
    </message>
</context>
<context>
    <name>core</name>
    <message>
        <source>The rank counts the platform&apos;s x and y, the carriage&apos;s z and the platform&apos;s tilt (its swing about the longitudinal axis). The actuators drive x_AB, x_CD and z; the tilt is not held by them. With the joints the document describes (spherical at the platform, one hinge per rod at the slider, a pair&apos;s rods one behind the other) the platform can tilt with the sliders locked; the document&apos;s kinematics assume it stays level.</source>
        <translation>Ранг учитывает x и y платформы, z каретки и наклон платформы (её качание вокруг продольной оси). Приводы задают x_AB, x_CD и z; наклон ими не удерживается. При шарнирах, описанных в статье (сферические у платформы, по одному шарниру на каждую тягу у ползуна, тяги одной пары одна за другой), платформа может наклоняться при застопоренных ползунах; кинематика статьи предполагает, что она остаётся горизонтальной.</translation>
    </message>
    <message>
        <source>%1 mm</source>
        <translation>%1 мм</translation>
    </message>
    <message>
        <source>mm</source>
        <translation>мм</translation>
    </message>
    <message>
        <source>mm²</source>
        <translation>мм²</translation>
    </message>
    <message>
        <source>N</source>
        <translation>Н</translation>
    </message>
    <message>
        <source>N·m</source>
        <translation>Н·м</translation>
    </message>
    <message>
        <source>mm/s</source>
        <translation>мм/с</translation>
    </message>
    <message>
        <source>rad/s</source>
        <translation>рад/с</translation>
    </message>
    <message>
        <source>mm/rad</source>
        <translation>мм/рад</translation>
    </message>
    <message>
        <source>mm/rad²</source>
        <translation>мм/рад²</translation>
    </message>
    <message>
        <source>mm²/rad</source>
        <translation>мм²/рад</translation>
    </message>
    <message>
        <source>rad/mm</source>
        <translation>рад/мм</translation>
    </message>
    <message>
        <source>mm/rev</source>
        <translation>мм/об</translation>
    </message>
    <message>
        <source>mm/step</source>
        <translation>мм/шаг</translation>
    </message>
    <message>
        <source>°/step</source>
        <translation>°/шаг</translation>
    </message>
    <message>
        <source>N·m/rad</source>
        <translation>Н·м/рад</translation>
    </message>
    <message>
        <source>mm⁴</source>
        <translation>мм⁴</translation>
    </message>
    <message>
        <source>rad²/mm²</source>
        <translation>рад²/мм²</translation>
    </message>
    <message>
        <source>(%1, %2) mm</source>
        <translation>(%1; %2) мм</translation>
    </message>
    <message>
        <source>[%1, %2]</source>
        <translation>[%1; %2]</translation>
    </message>
    <message>
        <source>%1 right of %2</source>
        <translation>%1 справа от %2</translation>
    </message>
    <message>
        <source>%1 left of %2</source>
        <translation>%1 слева от %2</translation>
    </message>
    <message>
        <source>length of crank 1, driven at A</source>
        <translation>длина кривошипа 1 (привод в A)</translation>
    </message>
    <message>
        <source>length of distal link 1, from B to C</source>
        <translation>длина шатуна 1, от B до C</translation>
    </message>
    <message>
        <source>length of distal link 2, from C to D</source>
        <translation>длина шатуна 2, от C до D</translation>
    </message>
    <message>
        <source>length of crank 2, driven at E</source>
        <translation>длина кривошипа 2 (привод в E)</translation>
    </message>
    <message>
        <source>length of the ground, from A to E along +x</source>
        <translation>длина стойки, от A до E вдоль +x</translation>
    </message>
    <message>
        <source>lower limit of crank angle θ₁</source>
        <translation>нижняя граница угла кривошипа θ₁</translation>
    </message>
    <message>
        <source>upper limit of crank angle θ₁</source>
        <translation>верхняя граница угла кривошипа θ₁</translation>
    </message>
    <message>
        <source>lower limit of crank angle θ₄</source>
        <translation>нижняя граница угла кривошипа θ₄</translation>
    </message>
    <message>
        <source>upper limit of crank angle θ₄</source>
        <translation>верхняя граница угла кривошипа θ₄</translation>
    </message>
    <message>
        <source>left</source>
        <translation>слева</translation>
    </message>
    <message>
        <source>right</source>
        <translation>справа</translation>
    </message>
    <message>
        <source>working mode of leg 1: elbow B left (+1) or right (−1) of A→C</source>
        <translation>рабочий режим ноги 1: шарнир B слева (+1) или справа (−1) от A→C</translation>
    </message>
    <message>
        <source>working mode of leg 2: elbow D left (+1) or right (−1) of E→C</source>
        <translation>рабочий режим ноги 2: шарнир D слева (+1) или справа (−1) от E→C</translation>
    </message>
    <message>
        <source>assembly mode: C left (+1) or right (−1) of B→D</source>
        <translation>вариант сборки: C слева (+1) или справа (−1) от B→D</translation>
    </message>
    <message>
        <source>%1 = %2 is invalid: it must be +1 (left) or -1 (right).</source>
        <translation>%1 = %2 — недопустимое значение: должно быть +1 (слева) или -1 (справа).</translation>
    </message>
    <message>
        <source>The five-bar linkage has no parameter named &apos;%1&apos;.</source>
        <translation>У пятизвенного механизма нет параметра «%1».</translation>
    </message>
    <message>
        <source>%1 = %2 must be less than %3 = %4.</source>
        <translation>%1 = %2 должно быть меньше %3 = %4.</translation>
    </message>
    <message>
        <source>%1 = %2 lies %3 above %4 = %5: a crank&apos;s range may span one turn (360°) at most.</source>
        <translation>%1 = %2 больше %4 = %5 на %3: диапазон кривошипа может охватывать не более одного оборота (360°).</translation>
    </message>
    <message>
        <source>%1 = %2 is not shorter than %3 = %4: the links cannot close the loop ABCDE for any crank angles (each link must be shorter than the other four together).</source>
        <translation>%1 = %2 не короче, чем %3 = %4: звенья не могут замкнуть контур ABCDE ни при каких углах кривошипов (каждое звено должно быть короче суммы остальных четырёх).</translation>
    </message>
    <message>
        <source>This five-bar has no workspace: with %1 the loop ABCDE never closes. Change a mode, a range or a length.</source>
        <translation>У этого пятизвенного механизма нет рабочего пространства: при %1 контур ABCDE не замыкается ни в одном положении. Измените режим, диапазон или длину.</translation>
    </message>
    <message>
        <source>This five-bar has no workspace: with %1 and the crank ranges %2 the loop ABCDE never closes. Change a mode, a range or a length.</source>
        <translation>У этого пятизвенного механизма нет рабочего пространства: при %1 и диапазонах кривошипов %2 контур ABCDE не замыкается ни в одном положении. Измените режим, диапазон или длину.</translation>
    </message>
    <message>
        <source>The workspace of these modes reaches direct singularities (the curves where the distal links BC and CD come in line, marked on the map): there C can move with both cranks held and the mechanism may switch its assembly mode. Keep the path of C away from them.</source>
        <translation>Рабочее пространство в этих режимах доходит до особых положений прямой кинематики (кривых, на которых шатуны BC и CD выстраиваются в одну линию; они отмечены на карте): там точка C может смещаться при обоих застопоренных кривошипах, а механизм — сменить вариант сборки. Держите траекторию C подальше от них.</translation>
    </message>
    <message>
        <source>crank AB angle at A, from +x counter-clockwise (actuated)</source>
        <translation>угол кривошипа AB в A, от +x против часовой стрелки (приводной)</translation>
    </message>
    <message>
        <source>crank ED angle at E, from +x counter-clockwise (actuated)</source>
        <translation>угол кривошипа ED в E, от +x против часовой стрелки (приводной)</translation>
    </message>
    <message>
        <source>output point C, x</source>
        <translation>выходная точка C, x</translation>
    </message>
    <message>
        <source>output point C, y</source>
        <translation>выходная точка C, y</translation>
    </message>
    <message>
        <source>At theta1 = %1, theta4 = %2 the distal links cannot meet: |BD| = %3 is more than BC + CD = %4 (past the dead point where BC and CD are stretched in line, a direct singularity).</source>
        <translation>При theta1 = %1, theta4 = %2 шатуны не могут сойтись: |BD| = %3 больше, чем BC + CD = %4 (за мёртвой точкой, где BC и CD вытянуты в одну линию, — особым положением прямой кинематики).</translation>
    </message>
    <message>
        <source>At theta1 = %1, theta4 = %2 the distal links cannot meet: |BD| = %3 is less than |BC − CD| = %4 (past the dead point where BC and CD fold in line, a direct singularity).</source>
        <translation>При theta1 = %1, theta4 = %2 шатуны не могут сойтись: |BD| = %3 меньше, чем |BC − CD| = %4 (за мёртвой точкой, где BC и CD складываются в одну линию, — особым положением прямой кинематики).</translation>
    </message>
    <message>
        <source>At theta1 = %1, theta4 = %2 the elbows B and D coincide and BC = CD: the position of C is undetermined.</source>
        <translation>При theta1 = %1, theta4 = %2 шарниры B и D совпадают, а BC = CD: положение C не определено.</translation>
    </message>
    <message>
        <source>At theta1 = %1, theta4 = %2 leg %3 would be in its other working mode (%4): crank %5 and link %6 pass through in line (an inverse singularity) on the way; switch %7 to go on.</source>
        <translation>При theta1 = %1, theta4 = %2 нога %3 оказалась бы в другом рабочем режиме (%4): по пути кривошип %5 и шатун %6 проходят через положение на одной прямой (особое положение обратной кинематики); чтобы продолжить, переключите %7.</translation>
    </message>
    <message>
        <source>C cannot reach %1: it lies %2 from %3, more than %4 + %5 = %6.</source>
        <translation>C не может достичь точки %1: она удалена от %3 на %2, это больше, чем %4 + %5 = %6.</translation>
    </message>
    <message>
        <source>C cannot reach %1: it lies %2 from %3, less than |%4 − %5| = %6.</source>
        <translation>C не может достичь точки %1: она удалена от %3 на %2, это меньше, чем |%4 − %5| = %6.</translation>
    </message>
    <message>
        <source>C = %1 lies on %2 and %3 = %4: the crank angle %5 is undetermined.</source>
        <translation>C = %1 совпадает с %2, а %3 = %4: угол кривошипа %5 не определён.</translation>
    </message>
    <message>
        <source>C cannot reach %1: crank %2 would have to be at %3 = %4, outside its range %5.</source>
        <translation>C не может достичь точки %1: кривошип %2 должен был бы стоять в %3 = %4, вне своего диапазона %5.</translation>
    </message>
    <message>
        <source>No failure.</source>
        <translation>Ошибки нет.</translation>
    </message>
    <message>
        <source>%1 must be a finite number.</source>
        <translation>%1 должно быть конечным числом.</translation>
    </message>
    <message>
        <source>%1 = %2 is outside the range of crank %3, %4: the crank turns fully, give its angle within it.</source>
        <translation>%1 = %2 вне диапазона кривошипа %3, %4: кривошип проворачивается полностью, задайте угол в этих пределах.</translation>
    </message>
    <message>
        <source>%1 = %2 is outside the range of crank %3, %4.</source>
        <translation>%1 = %2 вне диапазона кривошипа %3, %4.</translation>
    </message>
    <message>
        <source>crank AB angle at A, from +x counter-clockwise</source>
        <translation>угол кривошипа AB в A, от +x против часовой стрелки</translation>
    </message>
    <message>
        <source>crank ED angle at E, from +x counter-clockwise</source>
        <translation>угол кривошипа ED в E, от +x против часовой стрелки</translation>
    </message>
    <message>
        <source>J_x rows (C − B)ᵀ, (C − D)ᵀ</source>
        <translation>строки J_x: (C − B)ᵀ, (C − D)ᵀ</translation>
    </message>
    <message>
        <source>determinant of J (0: direct, ∞: inverse singularity)</source>
        <translation>определитель J (0 — особое положение прямой, ∞ — обратной кинематики)</translation>
    </message>
    <message>
        <source>0 at an inverse singularity (a leg stretched or folded)</source>
        <translation>0 в особом положении обратной кинематики (нога вытянута или сложена)</translation>
    </message>
    <message>
        <source>0 at a direct singularity (the distal links in line)</source>
        <translation>0 в особом положении прямой кинематики (шатуны на одной прямой)</translation>
    </message>
    <message>
        <source>condition number of J</source>
        <translation>число обусловленности J</translation>
    </message>
    <message>
        <source>angle ABC between crank AB and link BC (0°, 180°: inverse singularity)</source>
        <translation>угол ABC между кривошипом AB и шатуном BC (0°, 180° — особое положение обратной кинематики)</translation>
    </message>
    <message>
        <source>angle EDC between crank ED and link DC (0°, 180°: inverse singularity)</source>
        <translation>угол EDC между кривошипом ED и шатуном DC (0°, 180° — особое положение обратной кинематики)</translation>
    </message>
    <message>
        <source>angle BCD between the distal links (0°, 180°: direct singularity)</source>
        <translation>угол BCD между шатунами (0°, 180° — особое положение прямой кинематики)</translation>
    </message>
    <message>
        <source>transmission angle between the distal links, min(ψ, 180° − ψ)</source>
        <translation>угол передачи между шатунами, min(ψ, 180° − ψ)</translation>
    </message>
    <message>
        <source>distance from the inverse singularities, min |sin φ_i| (0 … 1)</source>
        <translation>удалённость от особых положений обратной кинематики, min |sin φ_i| (0 … 1)</translation>
    </message>
    <message>
        <source>distance from the direct singularities, |sin ψ| (0 … 1)</source>
        <translation>удалённость от особых положений прямой кинематики, |sin ψ| (0 … 1)</translation>
    </message>
    <message>
        <source>distance from the nearest singularity (0 … 1)</source>
        <translation>удалённость от ближайшего особого положения (0 … 1)</translation>
    </message>
    <message>
        <source>other assembly mode (C right of B→D, same crank angles)</source>
        <translation>другой вариант сборки (C справа от B→D, те же углы кривошипов)</translation>
    </message>
    <message>
        <source>other assembly mode (C left of B→D, same crank angles)</source>
        <translation>другой вариант сборки (C слева от B→D, те же углы кривошипов)</translation>
    </message>
    <message>
        <source>leg 1: other working mode (B left of A→C, same C)</source>
        <translation>нога 1: другой рабочий режим (B слева от A→C, та же точка C)</translation>
    </message>
    <message>
        <source>leg 1: other working mode (B right of A→C, same C)</source>
        <translation>нога 1: другой рабочий режим (B справа от A→C, та же точка C)</translation>
    </message>
    <message>
        <source>leg 2: other working mode (D left of E→C, same C)</source>
        <translation>нога 2: другой рабочий режим (D слева от E→C, та же точка C)</translation>
    </message>
    <message>
        <source>leg 2: other working mode (D right of E→C, same C)</source>
        <translation>нога 2: другой рабочий режим (D справа от E→C, та же точка C)</translation>
    </message>
    <message>
        <source>ground</source>
        <translation>стойка</translation>
    </message>
    <message>
        <source>crank AB</source>
        <translation>кривошип AB</translation>
    </message>
    <message>
        <source>link BC</source>
        <translation>шатун BC</translation>
    </message>
    <message>
        <source>link CD</source>
        <translation>шатун CD</translation>
    </message>
    <message>
        <source>crank DE</source>
        <translation>кривошип DE</translation>
    </message>
    <message>
        <source>planar five-bar: ground AE, cranks AB and DE (driven at A and E), distal links BC and CD</source>
        <translation>плоский пятизвенный механизм: стойка AE, кривошипы AB и DE (привод в A и E), шатуны BC и CD</translation>
    </message>
    <message>
        <source>drag to move C (inverse kinematics)</source>
        <translation>перетащите, чтобы переместить C (обратная кинематика)</translation>
    </message>
    <message>
        <source>drag to turn crank AB (sets θ₁, direct kinematics)</source>
        <translation>перетащите, чтобы повернуть кривошип AB (задаёт θ₁, прямая кинематика)</translation>
    </message>
    <message>
        <source>drag to turn crank DE (sets θ₄, direct kinematics)</source>
        <translation>перетащите, чтобы повернуть кривошип DE (задаёт θ₄, прямая кинематика)</translation>
    </message>
    <message>
        <source>No handle with that index.</source>
        <translation>Нет маркера с таким номером.</translation>
    </message>
    <message>
        <source>crank and distal link in line</source>
        <translation>кривошип и шатун на одной прямой</translation>
    </message>
    <message>
        <source>distal links in line</source>
        <translation>шатуны на одной прямой</translation>
    </message>
    <message>
        <source>leg 1 stretched (AB, BC in line)</source>
        <translation>нога 1 вытянута (AB, BC на одной прямой)</translation>
    </message>
    <message>
        <source>leg 1 folded (AB, BC in line)</source>
        <translation>нога 1 сложена (AB, BC на одной прямой)</translation>
    </message>
    <message>
        <source>leg 2 stretched (DE, CD in line)</source>
        <translation>нога 2 вытянута (DE, CD на одной прямой)</translation>
    </message>
    <message>
        <source>leg 2 folded (DE, CD in line)</source>
        <translation>нога 2 сложена (DE, CD на одной прямой)</translation>
    </message>
    <message>
        <source>rad/s²</source>
        <translation>рад/с²</translation>
    </message>
    <message>
        <source>crossed</source>
        <translation>скрещенная</translation>
    </message>
    <message>
        <source>open</source>
        <translation>открытая</translation>
    </message>
    <message>
        <source>crank-rocker</source>
        <translation>кривошипно-коромысловый</translation>
    </message>
    <message>
        <source>rocker-crank</source>
        <translation>коромыслово-кривошипный</translation>
    </message>
    <message>
        <source>double-crank</source>
        <translation>двухкривошипный</translation>
    </message>
    <message>
        <source>double-rocker</source>
        <translation>двухкоромысловый</translation>
    </message>
    <message>
        <source>triple-rocker</source>
        <translation>трёхкоромысловый</translation>
    </message>
    <message>
        <source>change-point</source>
        <translation>переходный</translation>
    </message>
    <message>
        <source>crank (input link) length</source>
        <translation>длина кривошипа (входного звена)</translation>
    </message>
    <message>
        <source>coupler length</source>
        <translation>длина шатуна</translation>
    </message>
    <message>
        <source>rocker (output link) length</source>
        <translation>длина коромысла (выходного звена)</translation>
    </message>
    <message>
        <source>ground (frame) length</source>
        <translation>длина стойки (неподвижного звена)</translation>
    </message>
    <message>
        <source>crank angular velocity, constant (positive: α grows, counter-clockwise)</source>
        <translation>угловая скорость кривошипа, постоянная (положительная: α растёт, против часовой стрелки)</translation>
    </message>
    <message>
        <source>coupler point M on BC: BM/BC (0 at B, 1 at C)</source>
        <translation>точка M шатуна на BC: BM/BC (0 в B, 1 в C)</translation>
    </message>
    <message>
        <source>assembly branch: +1 open (C left of B→D), −1 crossed</source>
        <translation>ветвь сборки: +1 открытая (C слева от B→D), −1 скрещенная</translation>
    </message>
    <message>
        <source>branch = %1 is invalid: it must be +1 (open) or -1 (crossed).</source>
        <translation>branch = %1 — недопустимое значение: должно быть +1 (открытая) или -1 (скрещенная).</translation>
    </message>
    <message>
        <source>The four-bar linkage has no parameter named &apos;%1&apos;.</source>
        <translation>У четырёхзвенного механизма нет параметра «%1».</translation>
    </message>
    <message>
        <source>%1 = %2 is not shorter than %3 = %4: the links cannot close the loop ABCD for any crank angle α (each link must be shorter than the other three together).</source>
        <translation>%1 = %2 не меньше, чем %3 = %4: звенья не замыкают контур ABCD ни при каком угле кривошипа α (каждое звено должно быть короче трёх остальных, вместе взятых).</translation>
    </message>
    <message>
        <source>at α = %1 the diagonal |BD| reaches BC + CD = %2: the coupler and the rocker are stretched in line (a dead point), and beyond it they cannot reach each other</source>
        <translation>при α = %1 диагональ |BD| достигает BC + CD = %2: шатун и коромысло вытянуты в одну линию (мёртвое положение), и дальше они не могут соединиться</translation>
    </message>
    <message>
        <source>at α = %1 the diagonal |BD| falls to |BC − CD| = %2: the coupler and the rocker are folded in line (a dead point), and beyond it they cannot close the loop</source>
        <translation>при α = %1 диагональ |BD| уменьшается до |BC − CD| = %2: шатун и коромысло сложены в одну линию (мёртвое положение), и дальше они не могут замкнуть контур</translation>
    </message>
    <message>
        <source>s + l = p + q (a change-point linkage): the links fold flat in line somewhere in the motion, where the open and crossed branches meet and a real linkage may switch branch.</source>
        <translation>s + l = p + q (переходный механизм): в каком-то положении звенья складываются в одну линию; там открытая и скрещенная ветви сходятся, и реальный механизм может перейти на другую ветвь.</translation>
    </message>
    <message>
        <source>The crank cannot turn fully: α is limited to [%1, %2], at whose ends the coupler and the rocker are in line (dead points where the crank cannot drive the rocker).</source>
        <translation>Кривошип не проворачивается полностью: α ограничен отрезком [%1, %2], на концах которого шатун и коромысло лежат на одной линии (мёртвые положения, в которых кривошип не может вести коромысло).</translation>
    </message>
    <message>
        <source>The transmission angle falls to %1 at α = %2 (below %3°): the crank drives the rocker poorly there.</source>
        <translation>Угол передачи падает до %1 при α = %2 (меньше %3°): здесь кривошип плохо передаёт движение коромыслу.</translation>
    </message>
    <message>
        <source>crank angle at A, from AD counter-clockwise (actuated)</source>
        <translation>угол кривошипа в A, от AD против часовой стрелки (ведущий)</translation>
    </message>
    <message>
        <source>rocker angle at D, from DA clockwise (output)</source>
        <translation>угол коромысла в D, от DA по часовой стрелке (выход)</translation>
    </message>
    <message>
        <source>alpha must be a finite number.</source>
        <translation>Значение alpha должно быть конечным числом.</translation>
    </message>
    <message>
        <source>alpha = %1 is outside [0°, 360°]: the crank turns fully, give its angle within one turn.</source>
        <translation>alpha = %1 вне [0°, 360°]: кривошип проворачивается полностью, задайте его угол в пределах одного оборота.</translation>
    </message>
    <message>
        <source>alpha = %1 is outside the range of the crank of this %2 linkage, [%3, %4]: %5.</source>
        <translation>alpha = %1 вне диапазона кривошипа этого механизма (тип по Грасгофу: %2), [%3, %4]: %5.</translation>
    </message>
    <message>
        <source>At alpha = %1 the crank joint B lies on D: the rocker&apos;s angle is undetermined.</source>
        <translation>При alpha = %1 шарнир кривошипа B совпадает с D: угол коромысла не определён.</translation>
    </message>
    <message>
        <source>The loop ABCD does not close at alpha = %1.</source>
        <translation>Контур ABCD не замыкается при alpha = %1.</translation>
    </message>
    <message>
        <source>delta must be a finite number.</source>
        <translation>Значение delta должно быть конечным числом.</translation>
    </message>
    <message>
        <source>delta = %1 is outside the range the rocker reaches in the crossed branch, [%2, %3]: at its ends the crank and the coupler are in line, or the crank is at its own limit.</source>
        <translation>delta = %1 вне диапазона, который коромысло проходит в скрещенной ветви, [%2, %3]: на его концах кривошип и шатун лежат на одной линии или кривошип находится на собственном пределе.</translation>
    </message>
    <message>
        <source>delta = %1 is outside the range the rocker reaches in the open branch, [%2, %3]: at its ends the crank and the coupler are in line, or the crank is at its own limit.</source>
        <translation>delta = %1 вне диапазона, который коромысло проходит в открытой ветви, [%2, %3]: на его концах кривошип и шатун лежат на одной линии или кривошип находится на собственном пределе.</translation>
    </message>
    <message>
        <source>At delta = %1 the rocker joint C lies on A: the crank angle is undetermined.</source>
        <translation>При delta = %1 шарнир коромысла C совпадает с A: угол кривошипа не определён.</translation>
    </message>
    <message>
        <source>The crank cannot reach the coupler at delta = %1: |AC| = %2 is not between |AB − BC| and AB + BC.</source>
        <translation>При delta = %1 кривошип не достаёт до шатуна: |AC| = %2 не лежит между |AB − BC| и AB + BC.</translation>
    </message>
    <message>
        <source>The rocker reaches delta = %1 only in the other assembly branch; this design is crossed.</source>
        <translation>Коромысло достигает delta = %1 только в другой ветви сборки; эта конструкция собрана в скрещенной ветви.</translation>
    </message>
    <message>
        <source>The rocker reaches delta = %1 only in the other assembly branch; this design is open.</source>
        <translation>Коромысло достигает delta = %1 только в другой ветви сборки; эта конструкция собрана в открытой ветви.</translation>
    </message>
    <message>
        <source>crank angle at A, from AD counter-clockwise</source>
        <translation>угол кривошипа в A, от AD против часовой стрелки</translation>
    </message>
    <message>
        <source>rocker angle at D, from DA clockwise</source>
        <translation>угол коромысла в D, от DA по часовой стрелке</translation>
    </message>
    <message>
        <source>transmission angle at C, from CB to CD counter-clockwise (&lt; 0: crossed)</source>
        <translation>угол передачи в C, от CB к CD против часовой стрелки (&lt; 0: скрещенная ветвь)</translation>
    </message>
    <message>
        <source>angle at D from DA to DB (4)</source>
        <translation>угол в D от DA к DB (4)</translation>
    </message>
    <message>
        <source>angle at B from BA to BC, 360° − (α + γ + δ)</source>
        <translation>угол в B от BA к BC, 360° − (α + γ + δ)</translation>
    </message>
    <message>
        <source>J_q = ∂F/∂α = 2·AB·BC·sin β (0: inverse singularity)</source>
        <translation>J_q = ∂F/∂α = 2·AB·BC·sin β (0: особое положение обратной кинематики)</translation>
    </message>
    <message>
        <source>J_x = −∂F/∂δ = −2·BC·CD·sin γ (0: direct singularity)</source>
        <translation>J_x = −∂F/∂δ = −2·BC·CD·sin γ (0: особое положение прямой кинематики)</translation>
    </message>
    <message>
        <source>α̇ = J·δ̇, J = J_q⁻¹·J_x = dα/dδ</source>
        <translation>α̇ = J·δ̇, J = J_q⁻¹·J_x = dα/dδ</translation>
    </message>
    <message>
        <source>transfer function dδ/dα = ω₃/ω₁ = −(9)</source>
        <translation>передаточная функция dδ/dα = ω₃/ω₁ = −(9)</translation>
    </message>
    <message>
        <source>crank angular velocity (constant)</source>
        <translation>угловая скорость кривошипа (постоянная)</translation>
    </message>
    <message>
        <source>coupler angular velocity, counter-clockwise</source>
        <translation>угловая скорость шатуна, против часовой стрелки</translation>
    </message>
    <message>
        <source>dδ/dt, exact (the document&apos;s (8) with the opposite sign)</source>
        <translation>dδ/dt, точное значение (формула (8) статьи с обратным знаком)</translation>
    </message>
    <message>
        <source>coupler angular acceleration, counter-clockwise</source>
        <translation>угловое ускорение шатуна, против часовой стрелки</translation>
    </message>
    <message>
        <source>d²δ/dt² at constant ω₁, exact (not the document&apos;s (14))</source>
        <translation>d²δ/dt² при постоянной ω₁, точное значение (не формула (14) статьи)</translation>
    </message>
    <message>
        <source>acute transmission angle min(|γ|, 180° − |γ|) (below 40°: poor)</source>
        <translation>острый угол передачи min(|γ|, 180° − |γ|) (меньше 40°: плохая передача)</translation>
    </message>
    <message>
        <source>distance from the nearest singularity, min(|sin β|, |sin γ|)</source>
        <translation>удалённость от ближайшего особого положения, min(|sin β|, |sin γ|)</translation>
    </message>
    <message>
        <source>diagonal |BD|</source>
        <translation>диагональ |BD|</translation>
    </message>
    <message>
        <source>coupler point M, x</source>
        <translation>точка шатуна M, x</translation>
    </message>
    <message>
        <source>coupler point M, y</source>
        <translation>точка шатуна M, y</translation>
    </message>
    <message>
        <source>instantaneous centre P of the coupler, x (none: AB ∥ DC)</source>
        <translation>мгновенный центр скоростей P шатуна, x (нет: AB ∥ DC)</translation>
    </message>
    <message>
        <source>instantaneous centre P of the coupler, y (none: AB ∥ DC)</source>
        <translation>мгновенный центр скоростей P шатуна, y (нет: AB ∥ DC)</translation>
    </message>
    <message>
        <source>assembly branch: open (C left of B→D) or crossed</source>
        <translation>ветвь сборки: открытая (C слева от B→D) или скрещенная</translation>
    </message>
    <message>
        <source>Grashof class from s + l against p + q</source>
        <translation>тип по Грасгофу: s + l в сравнении с p + q</translation>
    </message>
    <message>
        <source>crossed branch (same crank angle)</source>
        <translation>скрещенная ветвь (тот же угол кривошипа)</translation>
    </message>
    <message>
        <source>open branch (same crank angle)</source>
        <translation>открытая ветвь (тот же угол кривошипа)</translation>
    </message>
    <message>
        <source>ground AD</source>
        <translation>стойка AD</translation>
    </message>
    <message>
        <source>coupler BC</source>
        <translation>шатун BC</translation>
    </message>
    <message>
        <source>rocker CD</source>
        <translation>коромысло CD</translation>
    </message>
    <message>
        <source>planar four-bar: ground AD, crank AB (driven at A), coupler BC, rocker CD</source>
        <translation>плоский четырёхзвенный механизм: стойка AD, кривошип AB (привод в A), шатун BC, коромысло CD</translation>
    </message>
    <message>
        <source>BC (P at infinity: AB ∥ DC, the coupler translates)</source>
        <translation>BC (P в бесконечности: AB ∥ DC, шатун движется поступательно)</translation>
    </message>
    <message>
        <source>drag to turn the crank (sets α, direct kinematics)</source>
        <translation>перетащите, чтобы повернуть кривошип (задаёт α, прямая кинематика)</translation>
    </message>
    <message>
        <source>drag to swing the rocker (sets δ, inverse kinematics)</source>
        <translation>перетащите, чтобы качнуть коромысло (задаёт δ, обратная кинематика)</translation>
    </message>
    <message>
        <source>coupler curve of M (crossed branch)</source>
        <translation>шатунная кривая точки M (скрещенная ветвь)</translation>
    </message>
    <message>
        <source>coupler curve of M (open branch)</source>
        <translation>шатунная кривая точки M (открытая ветвь)</translation>
    </message>
    <message>
        <source>No joint variable with that index.</source>
        <translation>Нет обобщённой координаты с таким номером.</translation>
    </message>
    <message>
        <source>not a number</source>
        <translation>не число</translation>
    </message>
    <message>
        <source>%1 (%2) = %3 is invalid: it must be greater than %4.</source>
        <translation>%1 (%2) = %3 — недопустимое значение: оно должно быть больше %4.</translation>
    </message>
    <message>
        <source>%1 (%2) = %3 is invalid: it must be at least %4.</source>
        <translation>%1 (%2) = %3 — недопустимое значение: оно должно быть не меньше %4.</translation>
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
        <translation>%1 (%2) = %3 — недопустимое значение: оно должно лежать в пределах %4.</translation>
    </message>
    <message>
        <source>no kinematic chain is described for this mechanism</source>
        <translation>для этого механизма не описана кинематическая цепь</translation>
    </message>
    <message>
        <source>pair &apos;%1&apos; does not join two different links of the chain</source>
        <translation>пара «%1» не соединяет два разных звена цепи</translation>
    </message>
    <message>
        <source>pair &apos;%1&apos; has a point or an axis that is not finite</source>
        <translation>у пары «%1» точка или ось заданы не конечными числами</translation>
    </message>
    <message>
        <source>pair &apos;%1&apos; has no axis</source>
        <translation>у пары «%1» нет оси</translation>
    </message>
    <message>
        <source>the chain is marked planar (the plane z = 0) but pair &apos;%1&apos; is not</source>
        <translation>цепь отмечена как плоская (плоскость z = 0), но пара «%1» не лежит в ней</translation>
    </message>
    <message numerus="yes">
        <source>%n moving link(s)</source>
        <translation>
            <numerusform>%n подвижное звено</numerusform>
            <numerusform>%n подвижных звена</numerusform>
            <numerusform>%n подвижных звеньев</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n pair(s)</source>
        <translation>
            <numerusform>%n кинематическая пара</numerusform>
            <numerusform>%n кинематические пары</numerusform>
            <numerusform>%n кинематических пар</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n loop(s)</source>
        <translation>
            <numerusform>%n замкнутый контур</numerusform>
            <numerusform>%n замкнутых контура</numerusform>
            <numerusform>%n замкнутых контуров</numerusform>
        </translation>
    </message>
    <message>
        <source>Planar chain of %1, %2 and %3: the rank of its constraint Jacobian gives mobility %4</source>
        <translation>Плоская цепь (%1, %2 и %3): ранг её матрицы Якоби уравнений связей даёт подвижность %4</translation>
    </message>
    <message>
        <source>Spatial chain of %1, %2 and %3: the rank of its constraint Jacobian gives mobility %4</source>
        <translation>Пространственная цепь (%1, %2 и %3): ранг её матрицы Якоби уравнений связей даёт подвижность %4</translation>
    </message>
    <message numerus="yes">
        <source>Chebyshev&apos;s W = %1 is wrong: %n planar loop equation(s) is/are redundant (an overconstrained planar chain)</source>
        <translation>
            <numerusform>формула Чебышева даёт W = %1 — неверно: %n уравнение плоских контуров избыточно (плоская цепь с избыточными связями)</numerusform>
            <numerusform>формула Чебышева даёт W = %1 — неверно: %n уравнения плоских контуров избыточны (плоская цепь с избыточными связями)</numerusform>
            <numerusform>формула Чебышева даёт W = %1 — неверно: %n уравнений плоских контуров избыточны (плоская цепь с избыточными связями)</numerusform>
        </translation>
    </message>
    <message>
        <source>Chebyshev&apos;s W = %1 is right</source>
        <translation>формула Чебышева даёт W = %1 — верно</translation>
    </message>
    <message>
        <source>Somov–Malyshev&apos;s W = %1 is right</source>
        <translation>формула Сомова–Малышева даёт W = %1 — верно</translation>
    </message>
    <message>
        <source>(parallel axes: a planar loop imposes only 3)</source>
        <translation>(оси параллельны: плоский контур накладывает только 3)</translation>
    </message>
    <message>
        <source>(an overconstrained, &quot;paradoxical&quot; chain: it moves)</source>
        <translation>(«парадоксальная» цепь с избыточными связями: она подвижна)</translation>
    </message>
    <message>
        <source>(an overconstrained chain)</source>
        <translation>(цепь с избыточными связями)</translation>
    </message>
    <message numerus="yes">
        <source>Somov–Malyshev&apos;s W = %1 is wrong: it counts 6 equations per loop and %n is/are redundant %2</source>
        <translation>
            <numerusform>формула Сомова–Малышева даёт W = %1 — неверно: она считает 6 уравнений на контур, а %n из них избыточно %2</numerusform>
            <numerusform>формула Сомова–Малышева даёт W = %1 — неверно: она считает 6 уравнений на контур, а %n из них избыточны %2</numerusform>
            <numerusform>формула Сомова–Малышева даёт W = %1 — неверно: она считает 6 уравнений на контур, а %n из них избыточны %2</numerusform>
        </translation>
    </message>
    <message>
        <source>at this pose the rank drops: the instantaneous mobility is %1, a singular pose</source>
        <translation>в этом положении ранг падает: мгновенная подвижность равна %1 — особое положение</translation>
    </message>
    <message>
        <source>no pair is actuated</source>
        <translation>ни одна пара не снабжена приводом</translation>
    </message>
    <message numerus="yes">
        <source>%n freedom(s)</source>
        <translation>
            <numerusform>%n степень свободы</numerusform>
            <numerusform>%n степени свободы</numerusform>
            <numerusform>%n степеней свободы</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n actuated freedom(s) leave(s) %1 uncontrolled (under-actuated)</source>
        <translation>
            <numerusform>%n степень свободы с приводом: без управления остаётся %1 (приводов недостаточно)</numerusform>
            <numerusform>%n степени свободы с приводом: без управления остаётся %1 (приводов недостаточно)</numerusform>
            <numerusform>%n степеней свободы с приводом: без управления остаётся %1 (приводов недостаточно)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n actuated freedom(s) for mobility %1: redundantly actuated</source>
        <translation>
            <numerusform>%n степень свободы с приводом при подвижности %1: избыточное число приводов</numerusform>
            <numerusform>%n степени свободы с приводом при подвижности %1: избыточное число приводов</numerusform>
            <numerusform>%n степеней свободы с приводом при подвижности %1: избыточное число приводов</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n actuated freedom(s): fully actuated</source>
        <translation>
            <numerusform>%n степень свободы с приводом: механизм полностью управляем</numerusform>
            <numerusform>%n степени свободы с приводом: механизм полностью управляем</numerusform>
            <numerusform>%n степеней свободы с приводом: механизм полностью управляем</numerusform>
        </translation>
    </message>
    <message>
        <source>with the actuators locked it can still move instantaneously here (a direct singularity)</source>
        <translation>при застопоренных приводах цепь здесь ещё может мгновенно сместиться (особое положение прямой кинематики)</translation>
    </message>
    <message numerus="yes">
        <source>%n idle freedom(s) is/are included</source>
        <translation>
            <numerusform>включая местные степени свободы: %n</numerusform>
            <numerusform>включая местные степени свободы: %n</numerusform>
            <numerusform>включая местные степени свободы: %n</numerusform>
        </translation>
    </message>
    <message>
        <source>link %1</source>
        <translation>звено %1</translation>
    </message>
    <message>
        <source>ground OB</source>
        <translation>стойка OB</translation>
    </message>
    <message>
        <source>crank OC</source>
        <translation>кривошип OC</translation>
    </message>
    <message>
        <source>coupler CA</source>
        <translation>шатун CA</translation>
    </message>
    <message>
        <source>spatial parallelogram: four parallel revolute axes taken as a spatial chain</source>
        <translation>пространственный параллелограмм: четыре параллельные оси вращательных пар, рассматриваемые как пространственная цепь</translation>
    </message>
    <message>
        <source>Bennett linkage: four revolute axes, opposite links equal, a/sin α = b/sin β</source>
        <translation>механизм Беннетта: четыре оси вращательных пар, противоположные звенья равны, a/sin α = b/sin β</translation>
    </message>
    <message>
        <source>spatial 4R loop with random axes (not a Bennett linkage)</source>
        <translation>пространственный контур 4R со случайными осями (не механизм Беннетта)</translation>
    </message>
    <message>
        <source>ground AE</source>
        <translation>стойка AE</translation>
    </message>
    <message>
        <source>link DC</source>
        <translation>шатун DC</translation>
    </message>
    <message>
        <source>crank ED</source>
        <translation>кривошип ED</translation>
    </message>
    <message>
        <source>planar five-bar: ground, two driven cranks, two distal links</source>
        <translation>плоский пятизвенный механизм: стойка, два ведущих кривошипа, два шатуна</translation>
    </message>
    <message>
        <source>Cannot analyse the mobility: %1.</source>
        <translation>Не удаётся определить подвижность: %1.</translation>
    </message>
    <message>
        <source>crank BA</source>
        <translation>кривошип BA</translation>
    </message>
    <message>
        <source>%1 (back)</source>
        <translation>%1 (сзади)</translation>
    </message>
    <message>
        <source>%1 (front)</source>
        <translation>%1 (спереди)</translation>
    </message>
    <message>
        <source>base</source>
        <translation>основание</translation>
    </message>
    <message>
        <source>clevis</source>
        <translation>вилка</translation>
    </message>
    <message>
        <source>stepper motor</source>
        <translation>шаговый двигатель</translation>
    </message>
    <message>
        <source>lead screw</source>
        <translation>ходовой винт</translation>
    </message>
    <message>
        <source>rod end</source>
        <translation>шарнирный наконечник</translation>
    </message>
    <message>
        <source>guide %1</source>
        <translation>направляющая %1</translation>
    </message>
    <message>
        <source>end stop</source>
        <translation>упор</translation>
    </message>
    <message>
        <source>carriage %1</source>
        <translation>каретка %1</translation>
    </message>
    <message>
        <source>platform</source>
        <translation>платформа</translation>
    </message>
    <message>
        <source>guide 1 reference point, x</source>
        <translation>опорная точка направляющей 1, x</translation>
    </message>
    <message>
        <source>guide 1 reference point, y</source>
        <translation>опорная точка направляющей 1, y</translation>
    </message>
    <message>
        <source>guide 2 reference point, x</source>
        <translation>опорная точка направляющей 2, x</translation>
    </message>
    <message>
        <source>guide 2 reference point, y</source>
        <translation>опорная точка направляющей 2, y</translation>
    </message>
    <message>
        <source>direction of guide 1</source>
        <translation>ориентация направляющей 1</translation>
    </message>
    <message>
        <source>direction of guide 2</source>
        <translation>ориентация направляющей 2</translation>
    </message>
    <message>
        <source>turn of guide 1 from the vertical (α₁ = 270° + γ₁)</source>
        <translation>поворот направляющей 1 от вертикали (α₁ = 270° + γ₁)</translation>
    </message>
    <message>
        <source>turn of guide 2 from the vertical (α₂ = 270° + γ₂)</source>
        <translation>поворот направляющей 2 от вертикали (α₂ = 270° + γ₂)</translation>
    </message>
    <message>
        <source>length of link S₁</source>
        <translation>длина звена S₁</translation>
    </message>
    <message>
        <source>length of link S₂</source>
        <translation>длина звена S₂</translation>
    </message>
    <message>
        <source>start of the stroke</source>
        <translation>начало хода</translation>
    </message>
    <message>
        <source>end of the stroke</source>
        <translation>конец хода</translation>
    </message>
    <message>
        <source>working mode of leg 1: sign in p₁ = B₁ ± √…</source>
        <translation>рабочий режим ноги 1: знак в p₁ = B₁ ± √…</translation>
    </message>
    <message>
        <source>working mode of leg 2: sign in p₂ = B₂ ± √…</source>
        <translation>рабочий режим ноги 2: знак в p₂ = B₂ ± √…</translation>
    </message>
    <message>
        <source>assembly mode: +1 platform left of Z₁→Z₂</source>
        <translation>вариант сборки: +1 — платформа слева от Z₁→Z₂</translation>
    </message>
    <message>
        <source>links kept on the inner side of the guides (1: on)</source>
        <translation>звенья только с внутренней стороны направляющих (1: вкл.)</translation>
    </message>
    <message>
        <source>drawn width of a guide</source>
        <translation>ширина направляющей на рисунке</translation>
    </message>
    <message>
        <source>MOMA has no parameter named &apos;%1&apos;.</source>
        <translation>У MOMA нет параметра «%1».</translation>
    </message>
    <message>
        <source>%1 and %2 both turn guide %3: give one of them.</source>
        <translation>%1 и %2 оба задают поворот направляющей %3: укажите только один из них.</translation>
    </message>
    <message>
        <source>%1 = %2 is invalid: it must be -1 or +1.</source>
        <translation>%1 = %2 — недопустимое значение: должно быть -1 или +1.</translation>
    </message>
    <message>
        <source>one_side = %1 is invalid: it must be 0 (off) or 1 (on).</source>
        <translation>one_side = %1 — недопустимое значение: должно быть 0 (выкл.) или 1 (вкл.).</translation>
    </message>
    <message>
        <source>p_min = %1 mm must be less than p_max = %2 mm.</source>
        <translation>p_min = %1 мм должно быть меньше p_max = %2 мм.</translation>
    </message>
    <message>
        <source>The guides lie on one line and their strokes overlap: the slider joints Z₁ and Z₂ could coincide. Move R₂ or turn a guide.</source>
        <translation>Направляющие лежат на одной прямой, и их ходы перекрываются: шарниры ползунов Z₁ и Z₂ могут совпасть. Сместите R₂ или поверните направляющую.</translation>
    </message>
    <message>
        <source>This configuration has no workspace: with l₁ = %1 mm, l₂ = %2 mm and strokes [%3, %4] mm the links cannot meet in the chosen working and assembly modes.</source>
        <translation>У этой конфигурации нет рабочего пространства: при l₁ = %1 мм, l₂ = %2 мм и ходе [%3; %4] мм звенья не могут сойтись в выбранных рабочих режимах и варианте сборки.</translation>
    </message>
    <message>
        <source>The guides cross inside their strokes: the sliders can collide there.</source>
        <translation>Направляющие пересекаются в пределах хода: там ползуны могут столкнуться.</translation>
    </message>
    <message>
        <source>slider 1 position (actuated)</source>
        <translation>положение ползуна 1 (приводное)</translation>
    </message>
    <message>
        <source>slider 2 position (actuated)</source>
        <translation>положение ползуна 2 (приводное)</translation>
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
        <translation>звено S%1 оказалось бы с внешней стороны направляющей %2 (включено ограничение на одну сторону)</translation>
    </message>
    <message>
        <source>The slider joints Z₁ and Z₂ coincide at p₁ = %1 mm, p₂ = %2 mm: the platform position is undetermined.</source>
        <translation>Шарниры ползунов Z₁ и Z₂ совпадают при p₁ = %1 мм, p₂ = %2 мм: положение платформы не определено.</translation>
    </message>
    <message>
        <source>The links cannot meet at p₁ = %1 mm, p₂ = %2 mm: |Z₁Z₂| = %3 mm is more than l₁ + l₂ = %4 mm.</source>
        <translation>Звенья не могут сойтись при p₁ = %1 мм, p₂ = %2 мм: |Z₁Z₂| = %3 мм больше, чем l₁ + l₂ = %4 мм.</translation>
    </message>
    <message>
        <source>The links cannot meet at p₁ = %1 mm, p₂ = %2 mm: |Z₁Z₂| = %3 mm is less than |l₁ − l₂| = %4 mm.</source>
        <translation>Звенья не могут сойтись при p₁ = %1 мм, p₂ = %2 мм: |Z₁Z₂| = %3 мм меньше, чем |l₁ − l₂| = %4 мм.</translation>
    </message>
    <message>
        <source>At p₁ = %1 mm, p₂ = %2 mm leg %3 would be past perpendicular to its guide, in its other working mode (an inverse singularity lies between); switch the mode to go on.</source>
        <translation>При p₁ = %1 мм, p₂ = %2 мм нога %3 перешла бы через перпендикуляр к своей направляющей, в другой рабочий режим (между ними — особое положение обратной кинематики); чтобы продолжить, переключите режим.</translation>
    </message>
    <message>
        <source>At p₁ = %1 mm, p₂ = %2 mm %3.</source>
        <translation>При p₁ = %1 мм, p₂ = %2 мм %3.</translation>
    </message>
    <message>
        <source>The platform cannot reach %1: it lies more than l%2 = %3 mm from guide %4.</source>
        <translation>Платформа не может достичь точки %1: точка удалена от направляющей %4 более чем на l%2 = %3 мм.</translation>
    </message>
    <message>
        <source>The platform cannot reach %1: slider %2 would have to be at p%3 = %4 mm, outside its stroke [%5, %6] mm.</source>
        <translation>Платформа не может достичь точки %1: ползун %2 должен был бы стоять в p%3 = %4 мм, вне своего хода [%5; %6] мм.</translation>
    </message>
    <message>
        <source>The platform cannot reach %1 in this assembly mode: it would cross the line Z₁Z₂, where the links are collinear (a direct singularity); switch the assembly mode to go on.</source>
        <translation>Платформа не может достичь точки %1 в этом варианте сборки: она пересекла бы прямую Z₁Z₂, на которой звенья коллинеарны (особое положение прямой кинематики); чтобы продолжить, переключите вариант сборки.</translation>
    </message>
    <message>
        <source>The platform cannot reach %1: %2.</source>
        <translation>Платформа не может достичь точки %1: %2.</translation>
    </message>
    <message>
        <source>%1 = %2 mm is outside the stroke [%3, %4] mm.</source>
        <translation>%1 = %2 мм вне хода [%3; %4] мм.</translation>
    </message>
    <message>
        <source>slider 1 position</source>
        <translation>положение ползуна 1</translation>
    </message>
    <message>
        <source>slider 2 position</source>
        <translation>положение ползуна 2</translation>
    </message>
    <message>
        <source>J_x rows 2(P − Z_i) (20)</source>
        <translation>строки J_x: 2(P − Z_i) (20)</translation>
    </message>
    <message>
        <source>ṗ = J·Ṗ, J = −J_p⁻¹·J_x ((21) up to its sign)</source>
        <translation>ṗ = J·Ṗ, J = −J_p⁻¹·J_x ((21) с точностью до знака)</translation>
    </message>
    <message>
        <source>0 at an inverse singularity</source>
        <translation>0 в особом положении обратной кинематики</translation>
    </message>
    <message>
        <source>0 at a direct singularity</source>
        <translation>0 в особом положении прямой кинематики</translation>
    </message>
    <message>
        <source>angle between link S₁ and guide 1 (90°: inverse singularity)</source>
        <translation>угол между звеном S₁ и направляющей 1 (90° — особое положение обратной кинематики)</translation>
    </message>
    <message>
        <source>angle between link S₂ and guide 2 (90°: inverse singularity)</source>
        <translation>угол между звеном S₂ и направляющей 2 (90° — особое положение обратной кинематики)</translation>
    </message>
    <message>
        <source>angle between the links (0°, 180°: direct singularity)</source>
        <translation>угол между звеньями (0°, 180° — особое положение прямой кинематики)</translation>
    </message>
    <message>
        <source>other assembly mode (same slider positions)</source>
        <translation>другой вариант сборки (те же положения ползунов)</translation>
    </message>
    <message>
        <source>leg 1: other working mode (same platform position)</source>
        <translation>нога 1: другой рабочий режим (то же положение платформы)</translation>
    </message>
    <message>
        <source>leg 2: other working mode (same platform position)</source>
        <translation>нога 2: другой рабочий режим (то же положение платформы)</translation>
    </message>
    <message>
        <source>slider K₁</source>
        <translation>ползун K₁</translation>
    </message>
    <message>
        <source>slider K₂</source>
        <translation>ползун K₂</translation>
    </message>
    <message>
        <source>link S₁</source>
        <translation>звено S₁</translation>
    </message>
    <message>
        <source>link S₂</source>
        <translation>звено S₂</translation>
    </message>
    <message>
        <source>guide PO₁</source>
        <translation>направляющая PO₁</translation>
    </message>
    <message>
        <source>guide PO₂</source>
        <translation>направляющая PO₂</translation>
    </message>
    <message>
        <source>MOMA: two sliders on powered guides, two links meeting at the platform joint P</source>
        <translation>MOMA: два ползуна на приводных направляющих и два звена, соединённые шарниром платформы P</translation>
    </message>
    <message>
        <source>drag to move the platform (inverse kinematics)</source>
        <translation>перетащите, чтобы переместить платформу (обратная кинематика)</translation>
    </message>
    <message>
        <source>drag along guide 1 to set p₁ (direct kinematics)</source>
        <translation>перетащите вдоль направляющей 1, чтобы задать p₁ (прямая кинематика)</translation>
    </message>
    <message>
        <source>drag along guide 2 to set p₂ (direct kinematics)</source>
        <translation>перетащите вдоль направляющей 2, чтобы задать p₂ (прямая кинематика)</translation>
    </message>
    <message>
        <source>link ⟂ guide</source>
        <translation>звено ⟂ направляющей</translation>
    </message>
    <message>
        <source>links collinear</source>
        <translation>звенья коллинеарны</translation>
    </message>
    <message>
        <source>link 1 ⟂ guide 1</source>
        <translation>звено 1 ⟂ направляющей 1</translation>
    </message>
    <message>
        <source>link 2 ⟂ guide 2</source>
        <translation>звено 2 ⟂ направляющей 2</translation>
    </message>
    <message>
        <source>crossed (X)</source>
        <translation>скрещенная (X)</translation>
    </message>
    <message>
        <source>extended (O)</source>
        <translation>вытянутая (O)</translation>
    </message>
    <message>
        <source>rod length</source>
        <translation>длина стержня</translation>
    </message>
    <message>
        <source>platform width</source>
        <translation>ширина платформы</translation>
    </message>
    <message>
        <source>transverse guide length (slider positions 0…L)</source>
        <translation>длина поперечных направляющих (положения ползунов 0…L)</translation>
    </message>
    <message>
        <source>spacing of the transverse guides</source>
        <translation>расстояние между поперечными направляющими</translation>
    </message>
    <message>
        <source>start of the longitudinal travel</source>
        <translation>начало продольного хода</translation>
    </message>
    <message>
        <source>end of the longitudinal travel</source>
        <translation>конец продольного хода</translation>
    </message>
    <message>
        <source>+1 extended (O), −1 crossed (X)</source>
        <translation>+1 вытянутая (O), −1 скрещенная (X)</translation>
    </message>
    <message>
        <source>The O-X glide has no parameter named &apos;%1&apos;.</source>
        <translation>У механизма O-X glide нет параметра «%1».</translation>
    </message>
    <message>
        <source>mode = %1 is invalid: it must be +1 (O, extended) or -1 (X, crossed).</source>
        <translation>mode = %1 — недопустимое значение: должно быть +1 (O, вытянутая форма) или -1 (X, скрещенная).</translation>
    </message>
    <message>
        <source>mode must be +1 (O, extended) or -1 (X, crossed).</source>
        <translation>mode должно быть +1 (O, вытянутая форма) или -1 (X, скрещенная).</translation>
    </message>
    <message>
        <source>s = %1 must be less than 2l = %2: a platform that wide keeps the rods from ever crossing, so there is no X form.</source>
        <translation>s = %1 должно быть меньше 2l = %2: при такой широкой платформе стержни никогда не скрещиваются, и скрещенной (X) формы нет.</translation>
    </message>
    <message>
        <source>L = %1 must be more than the platform width s = %2: with guides that short the extended (O) form has no workspace.</source>
        <translation>L = %1 должно быть больше ширины платформы s = %2: при таких коротких направляющих у вытянутой (O) формы нет рабочего пространства.</translation>
    </message>
    <message>
        <source>z_min = %1 must be less than z_max = %2.</source>
        <translation>z_min = %1 должно быть меньше z_max = %2.</translation>
    </message>
    <message>
        <source>The crossed (X) form has no workspace with L = %1, s = %2 and l = %3.</source>
        <translation>У скрещенной (X) формы нет рабочего пространства при L = %1, s = %2 и l = %3.</translation>
    </message>
    <message>
        <source>The extended (O) form has no workspace with L = %1, s = %2 and l = %3.</source>
        <translation>У вытянутой (O) формы нет рабочего пространства при L = %1, s = %2 и l = %3.</translation>
    </message>
    <message>
        <source>slider pair AB position (actuated)</source>
        <translation>положение пары ползунов AB (приводное)</translation>
    </message>
    <message>
        <source>slider pair CD position (actuated)</source>
        <translation>положение пары ползунов CD (приводное)</translation>
    </message>
    <message>
        <source>longitudinal position (actuated serial axis)</source>
        <translation>продольное положение (приводная последовательная ось)</translation>
    </message>
    <message>
        <source>platform centre T, x</source>
        <translation>центр платформы T, x</translation>
    </message>
    <message>
        <source>platform centre T, y</source>
        <translation>центр платформы T, y</translation>
    </message>
    <message>
        <source>The platform cannot reach %1: y is more than the rod length l = %2.</source>
        <translation>Платформа не может достичь точки %1: y больше длины стержня l = %2.</translation>
    </message>
    <message>
        <source>The platform cannot reach %1: it would pass the rod joints&apos; plane y = 0, where the rods lie along the guides (a direct singularity).</source>
        <translation>Платформа не может достичь точки %1: она перешла бы через плоскость шарниров стержней y = 0, где стержни лежат вдоль направляющих (особое положение прямой кинематики).</translation>
    </message>
    <message>
        <source>The crossed (X) form cannot reach %1: slider pair %2 would have to be at %3 = %4, off its guides (0…%5 mm).</source>
        <translation>Скрещенная (X) форма не может достичь точки %1: пара ползунов %2 должна была бы оказаться в %3 = %4, за пределами своих направляющих (0…%5 мм).</translation>
    </message>
    <message>
        <source>The extended (O) form cannot reach %1: slider pair %2 would have to be at %3 = %4, off its guides (0…%5 mm).</source>
        <translation>Вытянутая (O) форма не может достичь точки %1: пара ползунов %2 должна была бы оказаться в %3 = %4, за пределами своих направляющих (0…%5 мм).</translation>
    </message>
    <message>
        <source>%1 = %2 is off the guides (%3…%4 mm).</source>
        <translation>%1 = %2 за пределами направляющих (%3…%4 мм).</translation>
    </message>
    <message>
        <source>%1 = %2 is outside the travel (%3…%4 mm).</source>
        <translation>%1 = %2 за пределами хода (%3…%4 мм).</translation>
    </message>
    <message>
        <source>The rods cannot reach the platform at x_AB = %1, x_CD = %2: |x_CD − x_AB − s| = %3 is more than 2l = %4.</source>
        <translation>Стержни не достают до платформы при x_AB = %1, x_CD = %2: |x_CD − x_AB − s| = %3 больше 2l = %4.</translation>
    </message>
    <message>
        <source>x_CD − x_AB = %1 is less than s = %2: these slider positions hold the crossed (X) form, and the mechanism is extended (O). At x_CD − x_AB = s the rods are parallel and the platform can swing (a singularity), so the pairs do not pass it on their own: switch the form to go on.</source>
        <translation>x_CD − x_AB = %1 меньше s = %2: такие положения ползунов соответствуют скрещенной (X) форме, а механизм находится в вытянутой (O). При x_CD − x_AB = s стержни параллельны и платформа может качаться (особое положение), поэтому пары ползунов сами его не проходят: чтобы продолжить, переключите форму.</translation>
    </message>
    <message>
        <source>x_CD − x_AB = %1 is more than s = %2: these slider positions hold the extended (O) form, and the mechanism is crossed (X). At x_CD − x_AB = s the rods are parallel and the platform can swing (a singularity), so the pairs do not pass it on their own: switch the form to go on.</source>
        <translation>x_CD − x_AB = %1 больше s = %2: такие положения ползунов соответствуют вытянутой (O) форме, а механизм находится в скрещенной (X). При x_CD − x_AB = s стержни параллельны и платформа может качаться (особое положение), поэтому пары ползунов сами его не проходят: чтобы продолжить, переключите форму.</translation>
    </message>
    <message>
        <source>slider pair AB position</source>
        <translation>положение пары ползунов AB</translation>
    </message>
    <message>
        <source>slider pair CD position</source>
        <translation>положение пары ползунов CD</translation>
    </message>
    <message>
        <source>longitudinal position</source>
        <translation>продольное положение</translation>
    </message>
    <message>
        <source>J_q = diag(−2u₁, −2u₂), u_i the rods&apos; runs along the guides</source>
        <translation>J_q = diag(−2u₁, −2u₂), u_i — проекции стержней на направляющие</translation>
    </message>
    <message>
        <source>J_x rows (2u_i, 2y)</source>
        <translation>строки J_x: (2u_i, 2y)</translation>
    </message>
    <message>
        <source>q̇ = J·ẋ of the planar part, J = −J_q⁻¹·J_x</source>
        <translation>q̇ = J·ẋ плоской части, J = −J_q⁻¹·J_x</translation>
    </message>
    <message>
        <source>angle between the rods and the guides (90°: the O↔X crossing)</source>
        <translation>угол между стержнями и направляющими (90°: переход O↔X)</translation>
    </message>
    <message>
        <source>distance from the O↔X crossing (0 there; &gt; 0 O, &lt; 0 X)</source>
        <translation>расстояние до перехода O↔X (0 на нём; &gt; 0 O, &lt; 0 X)</translation>
    </message>
    <message>
        <source>form of the pose: O extended, X crossed</source>
        <translation>форма положения: O вытянутая, X скрещенная</translation>
    </message>
    <message>
        <source>crossed (X) form (same platform position)</source>
        <translation>скрещенная (X) форма (то же положение платформы)</translation>
    </message>
    <message>
        <source>extended (O) form (same platform position)</source>
        <translation>вытянутая (O) форма (то же положение платформы)</translation>
    </message>
    <message>
        <source>rods ⟂ guides: the O↔X crossing</source>
        <translation>стержни ⟂ направляющим: переход O↔X</translation>
    </message>
    <message>
        <source>rods parallel: the platform can swing</source>
        <translation>стержни параллельны: платформа может качаться</translation>
    </message>
    <message>
        <source>rods along the guides</source>
        <translation>стержни вдоль направляющих</translation>
    </message>
    <message>
        <source>rods ⟂ guides</source>
        <translation>стержни ⟂ направляющим</translation>
    </message>
    <message>
        <source>drag to move the platform (inverse kinematics, in the current form)</source>
        <translation>перетащите, чтобы переместить платформу (обратная кинематика, в текущей форме)</translation>
    </message>
    <message>
        <source>drag along the guides to set x_AB (direct kinematics)</source>
        <translation>перетащите вдоль направляющих, чтобы задать x_AB (прямая кинематика)</translation>
    </message>
    <message>
        <source>drag along the guides to set x_CD (direct kinematics)</source>
        <translation>перетащите вдоль направляющих, чтобы задать x_CD (прямая кинематика)</translation>
    </message>
    <message>
        <source>longitudinal carriage</source>
        <translation>продольная каретка</translation>
    </message>
    <message>
        <source>end plate</source>
        <translation>торцевая плита</translation>
    </message>
    <message>
        <source>longitudinal guide</source>
        <translation>продольная направляющая</translation>
    </message>
    <message>
        <source>slider %1</source>
        <translation>ползун %1</translation>
    </message>
    <message>
        <source>compensation element %1</source>
        <translation>компенсирующий элемент %1</translation>
    </message>
    <message>
        <source>rod joint %1</source>
        <translation>шарнир стержня %1</translation>
    </message>
    <message>
        <source>pair AB</source>
        <translation>пара AB</translation>
    </message>
    <message>
        <source>pair CD</source>
        <translation>пара CD</translation>
    </message>
    <message>
        <source>rod %1</source>
        <translation>стержень %1</translation>
    </message>
    <message>
        <source>spherical joint %1</source>
        <translation>сферический шарнир %1</translation>
    </message>
    <message>
        <source>carriage</source>
        <translation>каретка</translation>
    </message>
    <message>
        <source>slider pair AB</source>
        <translation>пара ползунов AB</translation>
    </message>
    <message>
        <source>slider pair CD</source>
        <translation>пара ползунов CD</translation>
    </message>
    <message>
        <source>O-X glide: carriage on the longitudinal guides, slider pairs AB and CD, four rods (revolute at the sliders, spherical at the platform), platform</source>
        <translation>O-X glide: каретка на продольных направляющих, пары ползунов AB и CD, четыре стержня (вращательные шарниры на ползунах, сферические на платформе), платформа</translation>
    </message>
    <message>
        <source>crank (lever) length</source>
        <translation>длина кривошипа (рычага)</translation>
    </message>
    <message>
        <source>base and coupler length</source>
        <translation>длина стойки и шатуна</translation>
    </message>
    <message>
        <source>ratio k = b/a</source>
        <translation>отношение k = b/a</translation>
    </message>
    <message>
        <source>lower limit of θ</source>
        <translation>нижний предел θ</translation>
    </message>
    <message>
        <source>upper limit of θ</source>
        <translation>верхний предел θ</translation>
    </message>
    <message>
        <source>lead of the screw</source>
        <translation>ход резьбы винта</translation>
    </message>
    <message>
        <source>linear step</source>
        <translation>линейный шаг</translation>
    </message>
    <message>
        <source>max. linear speed</source>
        <translation>макс. линейная скорость</translation>
    </message>
    <message>
        <source>max. thrust force</source>
        <translation>макс. осевое усилие</translation>
    </message>
    <message>
        <source>screw efficiency</source>
        <translation>КПД винтовой передачи</translation>
    </message>
    <message>
        <source>motor body length</source>
        <translation>длина корпуса двигателя</translation>
    </message>
    <message>
        <source>motor body width</source>
        <translation>ширина корпуса двигателя</translation>
    </message>
    <message>
        <source>screw diameter</source>
        <translation>диаметр винта</translation>
    </message>
    <message>
        <source>k = b/a = %1 is out of proportion: it must lie between 1e-6 and 1e6.</source>
        <translation>k = b/a = %1 — нереальное соотношение: оно должно лежать между 1e-6 и 1e6.</translation>
    </message>
    <message>
        <source>theta_min = %1° must be less than theta_max = %2°.</source>
        <translation>theta_min = %1° должно быть меньше theta_max = %2°.</translation>
    </message>
    <message>
        <source>k = %1 and b = %2 mm both set the coupler: give b or k, not both.</source>
        <translation>k = %1 и b = %2 мм оба задают длину шатуна: укажите b или k, но не оба сразу.</translation>
    </message>
    <message>
        <source>The П-joint has no parameter named &apos;%1&apos;.</source>
        <translation>У П-шарнира нет параметра «%1».</translation>
    </message>
    <message>
        <source>theta_max = %1° must be greater than theta_min = %2°.</source>
        <translation>theta_max = %1° должно быть больше theta_min = %2°.</translation>
    </message>
    <message>
        <source>The motor body (%1 mm) is longer than d_min = %2 mm: the diagonal cannot retract that far.</source>
        <translation>Корпус двигателя (%1 мм) длиннее, чем d_min = %2 мм: диагональ не может укоротиться настолько.</translation>
    </message>
    <message>
        <source>diagonal length (actuated)</source>
        <translation>длина диагонали (приводная)</translation>
    </message>
    <message>
        <source>output angle</source>
        <translation>выходной угол</translation>
    </message>
    <message>
        <source>d = %1 mm is outside the stroke [%2, %3] mm that the θ range allows.</source>
        <translation>d = %1 мм выходит за пределы хода [%2; %3] мм, допускаемого диапазоном θ.</translation>
    </message>
    <message>
        <source>θ = %1° is outside the design range [%2, %3]°.</source>
        <translation>θ = %1° выходит за пределы конструктивного диапазона [%2; %3]°.</translation>
    </message>
    <message>
        <source>diagonal length</source>
        <translation>длина диагонали</translation>
    </message>
    <message>
        <source>passive angle of the diagonal</source>
        <translation>пассивный угол диагонали</translation>
    </message>
    <message>
        <source>transmission angle</source>
        <translation>угол передачи</translation>
    </message>
    <message>
        <source>Jacobian ḋ = J·θ̇</source>
        <translation>якобиан ḋ = J·θ̇</translation>
    </message>
    <message>
        <source>inverse Jacobian θ̇ = J⁻¹·ḋ</source>
        <translation>обратный якобиан θ̇ = J⁻¹·ḋ</translation>
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
        <translation>производная J</translation>
    </message>
    <message>
        <source>output torque at F_max</source>
        <translation>выходной момент при F_max</translation>
    </message>
    <message>
        <source>output speed θ̇ at ḋ_max</source>
        <translation>выходная скорость θ̇ при ḋ_max</translation>
    </message>
    <message>
        <source>output resolution per step</source>
        <translation>выходное разрешение на шаг</translation>
    </message>
    <message>
        <source>motor torque at F_max</source>
        <translation>момент двигателя при F_max</translation>
    </message>
    <message>
        <source>diagonal at θ_min</source>
        <translation>диагональ при θ_min</translation>
    </message>
    <message>
        <source>diagonal at θ_max</source>
        <translation>диагональ при θ_max</translation>
    </message>
    <message>
        <source>actuator stroke</source>
        <translation>ход привода</translation>
    </message>
    <message>
        <source>recommended range from (J ≥ 60 % of best)</source>
        <translation>рекомендуемый диапазон: от (J ≥ 60 % наибольшего)</translation>
    </message>
    <message>
        <source>recommended range to (J ≥ 60 % of best)</source>
        <translation>рекомендуемый диапазон: до (J ≥ 60 % наибольшего)</translation>
    </message>
    <message>
        <source>motor body</source>
        <translation>корпус двигателя</translation>
    </message>
    <message>
        <source>screw</source>
        <translation>винт</translation>
    </message>
    <message>
        <source>O (motor)</source>
        <translation>O (двигатель)</translation>
    </message>
    <message>
        <source>A (screw)</source>
        <translation>A (винт)</translation>
    </message>
    <message>
        <source>active П-joint: hinged parallelogram OBAC with the telescopic diagonal OA (motor body and screw)</source>
        <translation>активный П-шарнир: шарнирный параллелограмм OBAC с телескопической диагональю OA (корпус двигателя и винт)</translation>
    </message>
    <message>
        <source>drag A to set θ</source>
        <translation>перетащите A, чтобы задать θ</translation>
    </message>
    <message>
        <source>drag C to set θ</source>
        <translation>перетащите C, чтобы задать θ</translation>
    </message>
    <message>
        <source>The pointer is on the pivot: θ is undefined there.</source>
        <translation>Указатель находится на оси вращения: здесь угол θ не определён.</translation>
    </message>
    <message>
        <source>Active П-joint</source>
        <translation>Активный П-шарнир</translation>
    </message>
    <message>
        <source>MOMA 2-axis parallel mechanism</source>
        <translation>Двухкоординатный параллельный механизм MOMA</translation>
    </message>
    <message>
        <source>O-X glide hybrid mechanism</source>
        <translation>Гибридный механизм O-X glide</translation>
    </message>
    <message>
        <source>Planar four-bar linkage</source>
        <translation>Плоский шарнирный четырёхзвенник</translation>
    </message>
    <message>
        <source>Planar five-bar linkage</source>
        <translation>Плоский шарнирный пятизвенник</translation>
    </message>
    <message>
        <source>Unknown mechanism kind &apos;%1&apos;.</source>
        <translation>Неизвестный тип механизма «%1».</translation>
    </message>
    <message>
        <source>A %1 has no parameter named &apos;%2&apos;.</source>
        <translation>У механизма «%1» нет параметра «%2».</translation>
    </message>
    <message>
        <source>link</source>
        <translation>звено</translation>
    </message>
    <message>
        <source>motor</source>
        <translation>двигатель</translation>
    </message>
    <message>
        <source>motor %1</source>
        <translation>двигатель %1</translation>
    </message>
    <message>
        <source>screw %1</source>
        <translation>винт %1</translation>
    </message>
    <message>
        <source>guide</source>
        <translation>направляющая</translation>
    </message>
    <message>
        <source>end stop %1</source>
        <translation>упор %1</translation>
    </message>
    <message>
        <source>slider</source>
        <translation>ползун</translation>
    </message>
    <message>
        <source>support</source>
        <translation>опора</translation>
    </message>
    <message>
        <source>support %1</source>
        <translation>опора %1</translation>
    </message>
    <message>
        <source>point</source>
        <translation>точка</translation>
    </message>
    <message>
        <source>point %1</source>
        <translation>точка %1</translation>
    </message>
    <message>
        <source>joint</source>
        <translation>шарнир</translation>
    </message>
    <message>
        <source>joint %1</source>
        <translation>шарнир %1</translation>
    </message>
    <message>
        <source>one side</source>
        <translation>одна сторона</translation>
    </message>
    <message>
        <source>form</source>
        <translation>форма</translation>
    </message>
    <message>
        <source>input of leg 1</source>
        <translation>вход ноги 1</translation>
    </message>
    <message>
        <source>input of leg 2</source>
        <translation>вход ноги 2</translation>
    </message>
    <message>
        <source>input of leg 3</source>
        <translation>вход ноги 3</translation>
    </message>
    <message>
        <source>platform angle</source>
        <translation>угол платформы</translation>
    </message>
    <message>
        <source>J_q = diag(∂g_i/∂q_i)</source>
        <translation>J_q = диаг(∂g_i/∂q_i)</translation>
    </message>
    <message>
        <source>J_x rows −∂g_i/∂X</source>
        <translation>строки J_x: −∂g_i/∂X</translation>
    </message>
    <message>
        <source>q̇ = J·Ẋ, J = J_q⁻¹·J_x</source>
        <translation>q̇ = J·Ẋ, J = J_q⁻¹·J_x</translation>
    </message>
    <message>
        <source>other assembly mode (same inputs)</source>
        <translation>другой режим сборки (те же входы)</translation>
    </message>
    <message>
        <source>leg 1: other working mode (same platform pose)</source>
        <translation>нога 1: другой рабочий режим (та же поза платформы)</translation>
    </message>
    <message>
        <source>leg 2: other working mode (same platform pose)</source>
        <translation>нога 2: другой рабочий режим (та же поза платформы)</translation>
    </message>
    <message>
        <source>leg 3: other working mode (same platform pose)</source>
        <translation>нога 3: другой рабочий режим (та же поза платформы)</translation>
    </message>
    <message>
        <source>%1 = %2 is invalid: it must be a whole number.</source>
        <translation>%1 = %2 недопустимо: должно быть целым числом.</translation>
    </message>
    <message>
        <source>The planar parallel mechanism has no parameter named &apos;%1&apos;.</source>
        <translation>У плоского параллельного механизма нет параметра «%1».</translation>
    </message>
    <message>
        <source>platform: 0 a point (2 DOF), 1 constant orientation (2 DOF), 2 free (3 DOF)</source>
        <translation>платформа: 0 точка (2 степени свободы), 1 постоянная ориентация (2 степени свободы), 2 свободная (3 степени свободы)</translation>
    </message>
    <message>
        <source>leg 1: type (0 R̲RR, 1 P̲RR, 2 RP̲R, 3 П̲RR)</source>
        <translation>нога 1: тип (0 R̲RR, 1 P̲RR, 2 RP̲R, 3 П̲RR)</translation>
    </message>
    <message>
        <source>leg 1: base point A₁, x</source>
        <translation>нога 1: точка основания A₁, x</translation>
    </message>
    <message>
        <source>leg 1: base point A₁, y</source>
        <translation>нога 1: точка основания A₁, y</translation>
    </message>
    <message>
        <source>leg 1: platform point B₁ in the platform frame, x</source>
        <translation>нога 1: точка платформы B₁ в системе платформы, x</translation>
    </message>
    <message>
        <source>leg 1: platform point B₁ in the platform frame, y</source>
        <translation>нога 1: точка платформы B₁ в системе платформы, y</translation>
    </message>
    <message>
        <source>leg 1: crank length (R̲RR)</source>
        <translation>нога 1: длина кривошипа (R̲RR)</translation>
    </message>
    <message>
        <source>leg 1: distal link length</source>
        <translation>нога 1: длина дистального звена</translation>
    </message>
    <message>
        <source>leg 1: direction of the guide (P̲RR) or of the П-joint base (П̲RR)</source>
        <translation>нога 1: направление направляющей (P̲RR) или основания П-шарнира (П̲RR)</translation>
    </message>
    <message>
        <source>leg 1: П-joint crank (lever) length</source>
        <translation>нога 1: длина кривошипа П-шарнира</translation>
    </message>
    <message>
        <source>leg 1: П-joint ratio k = b/a</source>
        <translation>нога 1: отношение П-шарнира k = b/a</translation>
    </message>
    <message>
        <source>leg 1: working mode (+1 elbow left of A₁→P₁; P̲RR: sign in q = B ± √…)</source>
        <translation>нога 1: рабочий режим (+1 локоть слева от A₁→P₁; P̲RR: знак в q = B ± √…)</translation>
    </message>
    <message>
        <source>leg 2: type (0 R̲RR, 1 P̲RR, 2 RP̲R, 3 П̲RR)</source>
        <translation>нога 2: тип (0 R̲RR, 1 P̲RR, 2 RP̲R, 3 П̲RR)</translation>
    </message>
    <message>
        <source>leg 2: base point A₂, x</source>
        <translation>нога 2: точка основания A₂, x</translation>
    </message>
    <message>
        <source>leg 2: base point A₂, y</source>
        <translation>нога 2: точка основания A₂, y</translation>
    </message>
    <message>
        <source>leg 2: platform point B₂ in the platform frame, x</source>
        <translation>нога 2: точка платформы B₂ в системе платформы, x</translation>
    </message>
    <message>
        <source>leg 2: platform point B₂ in the platform frame, y</source>
        <translation>нога 2: точка платформы B₂ в системе платформы, y</translation>
    </message>
    <message>
        <source>leg 2: crank length (R̲RR)</source>
        <translation>нога 2: длина кривошипа (R̲RR)</translation>
    </message>
    <message>
        <source>leg 2: distal link length</source>
        <translation>нога 2: длина дистального звена</translation>
    </message>
    <message>
        <source>leg 2: direction of the guide (P̲RR) or of the П-joint base (П̲RR)</source>
        <translation>нога 2: направление направляющей (P̲RR) или основания П-шарнира (П̲RR)</translation>
    </message>
    <message>
        <source>leg 2: П-joint crank (lever) length</source>
        <translation>нога 2: длина кривошипа П-шарнира</translation>
    </message>
    <message>
        <source>leg 2: П-joint ratio k = b/a</source>
        <translation>нога 2: отношение П-шарнира k = b/a</translation>
    </message>
    <message>
        <source>leg 2: working mode (+1 elbow left of A₂→P₂; P̲RR: sign in q = B ± √…)</source>
        <translation>нога 2: рабочий режим (+1 локоть слева от A₂→P₂; P̲RR: знак в q = B ± √…)</translation>
    </message>
    <message>
        <source>leg 3: type (0 R̲RR, 1 P̲RR, 2 RP̲R, 3 П̲RR)</source>
        <translation>нога 3: тип (0 R̲RR, 1 P̲RR, 2 RP̲R, 3 П̲RR)</translation>
    </message>
    <message>
        <source>leg 3: base point A₃, x</source>
        <translation>нога 3: точка основания A₃, x</translation>
    </message>
    <message>
        <source>leg 3: base point A₃, y</source>
        <translation>нога 3: точка основания A₃, y</translation>
    </message>
    <message>
        <source>leg 3: platform point B₃ in the platform frame, x</source>
        <translation>нога 3: точка платформы B₃ в системе платформы, x</translation>
    </message>
    <message>
        <source>leg 3: platform point B₃ in the platform frame, y</source>
        <translation>нога 3: точка платформы B₃ в системе платформы, y</translation>
    </message>
    <message>
        <source>leg 3: crank length (R̲RR)</source>
        <translation>нога 3: длина кривошипа (R̲RR)</translation>
    </message>
    <message>
        <source>leg 3: distal link length</source>
        <translation>нога 3: длина дистального звена</translation>
    </message>
    <message>
        <source>leg 3: direction of the guide (P̲RR) or of the П-joint base (П̲RR)</source>
        <translation>нога 3: направление направляющей (P̲RR) или основания П-шарнира (П̲RR)</translation>
    </message>
    <message>
        <source>leg 3: П-joint crank (lever) length</source>
        <translation>нога 3: длина кривошипа П-шарнира</translation>
    </message>
    <message>
        <source>leg 3: П-joint ratio k = b/a</source>
        <translation>нога 3: отношение П-шарнира k = b/a</translation>
    </message>
    <message>
        <source>leg 3: working mode (+1 elbow left of A₃→P₃; P̲RR: sign in q = B ± √…)</source>
        <translation>нога 3: рабочий режим (+1 локоть слева от A₃→P₃; P̲RR: знак в q = B ± √…)</translation>
    </message>
    <message>
        <source>assembly mode: 2 DOF +1 platform left of C₁→C₂, −1 right; 3 DOF the n-th solution in order of φ</source>
        <translation>режим сборки: при 2 степенях свободы +1 платформа слева от C₁→C₂, −1 справа; при 3 — n-е решение по возрастанию φ</translation>
    </message>
    <message>
        <source>platform angle φ of the workspace map (3 DOF)</source>
        <translation>угол платформы φ для карты рабочего пространства (3 степени свободы)</translation>
    </message>
    <message>
        <source>%1 must be less than %2.</source>
        <translation>%1 должно быть меньше %2.</translation>
    </message>
    <message>
        <source>The range of crank %1 spans more than one turn (360°).</source>
        <translation>Диапазон кривошипа %1 больше одного оборота (360°).</translation>
    </message>
    <message>
        <source>%1 must be positive: it is the length of strut %2.</source>
        <translation>%1 должно быть положительным: это длина штанги %2.</translation>
    </message>
    <message>
        <source>The diagonal of П-joint %1 must stay strictly between %2 mm and %3 mm (θ between −90° and 90°).</source>
        <translation>Диагональ П-шарнира %1 должна быть строго между %2 мм и %3 мм (θ между −90° и 90°).</translation>
    </message>
    <message>
        <source>A platform of constant orientation needs P̲RR or П̲RR legs: leg %1&apos;s distal parallelogram must hang from a body that does not turn.</source>
        <translation>Платформе постоянной ориентации нужны ноги P̲RR или П̲RR: дистальный параллелограмм ноги %1 должен висеть на звене, которое не поворачивается.</translation>
    </message>
    <message>
        <source>The assembly mode of a 3-DOF platform counts the solutions from 1.</source>
        <translation>Режим сборки платформы с 3 степенями свободы считает решения от 1.</translation>
    </message>
    <message>
        <source>The platform points B₁, B₂, B₃ coincide: the platform&apos;s angle is undetermined.</source>
        <translation>Точки платформы B₁, B₂, B₃ совпадают: угол платформы не определён.</translation>
    </message>
    <message>
        <source>The mechanism cannot be assembled anywhere in its input ranges and modes.</source>
        <translation>Механизм нельзя собрать нигде в его диапазонах входов и режимах.</translation>
    </message>
    <message>
        <source>input of leg 1 (actuated)</source>
        <translation>вход ноги 1 (приводной)</translation>
    </message>
    <message>
        <source>input of leg 2 (actuated)</source>
        <translation>вход ноги 2 (приводной)</translation>
    </message>
    <message>
        <source>input of leg 3 (actuated)</source>
        <translation>вход ноги 3 (приводной)</translation>
    </message>
    <message>
        <source>The number of inputs does not match the legs.</source>
        <translation>Число входов не совпадает с числом ног.</translation>
    </message>
    <message>
        <source>%1 = %2 is outside its range [%3, %4].</source>
        <translation>%1 = %2 вне своего диапазона [%3, %4].</translation>
    </message>
    <message>
        <source>The П-joint of leg %1 cannot take the diagonal %2 = %3 mm.</source>
        <translation>П-шарнир ноги %1 не может принять диагональ %2 = %3 мм.</translation>
    </message>
    <message>
        <source>The legs cannot be assembled at these inputs in the design&apos;s working and assembly modes.</source>
        <translation>При этих входах ноги нельзя собрать в рабочих режимах и режиме сборки проекта.</translation>
    </message>
    <message>
        <source>At these inputs the platform has %1 assembly modes in the design&apos;s working modes, fewer than assembly = %2.</source>
        <translation>При этих входах у платформы %1 режимов сборки в рабочих режимах проекта, меньше чем assembly = %2.</translation>
    </message>
    <message>
        <source>(%1, %2) mm, φ = %3°</source>
        <translation>(%1, %2) мм, φ = %3°</translation>
    </message>
    <message>
        <source>The platform cannot reach %1 in this assembly mode: the legs would pass through a direct singularity; switch the assembly mode to go on.</source>
        <translation>Платформа не может достичь %1 в этом режиме сборки: ноги прошли бы через особое положение прямой кинематики; чтобы продолжить, смените режим сборки.</translation>
    </message>
    <message>
        <source>the input of leg %1 would leave its range</source>
        <translation>вход ноги %1 вышел бы из своего диапазона</translation>
    </message>
    <message>
        <source>the input of leg %1 is undetermined there</source>
        <translation>вход ноги %1 там не определён</translation>
    </message>
    <message>
        <source>leg %1 cannot reach it</source>
        <translation>нога %1 не достаёт до неё</translation>
    </message>
    <message>
        <source>a leg&apos;s proximal and distal links in line</source>
        <translation>проксимальное и дистальное звенья ноги на одной прямой</translation>
    </message>
    <message>
        <source>the platform gains a freedom</source>
        <translation>платформа получает свободу</translation>
    </message>
    <message>
        <source>crank %1</source>
        <translation>кривошип %1</translation>
    </message>
    <message>
        <source>strut %1, motor body</source>
        <translation>штанга %1, корпус двигателя</translation>
    </message>
    <message>
        <source>strut %1, rod</source>
        <translation>штанга %1, шток</translation>
    </message>
    <message>
        <source>П-joint %1: crank OC</source>
        <translation>П-шарнир %1: кривошип OC</translation>
    </message>
    <message>
        <source>П-joint %1: coupler</source>
        <translation>П-шарнир %1: шатун</translation>
    </message>
    <message>
        <source>П-joint %1: motor body</source>
        <translation>П-шарнир %1: корпус двигателя</translation>
    </message>
    <message>
        <source>П-joint %1: screw</source>
        <translation>П-шарнир %1: винт</translation>
    </message>
    <message>
        <source>link %1, parallel</source>
        <translation>звено %1, параллельное</translation>
    </message>
    <message>
        <source>planar parallel mechanism: legs from the leg library joined at the platform</source>
        <translation>плоский параллельный механизм: ноги из библиотеки ног, соединённые платформой</translation>
    </message>
    <message>
        <source>Planar parallel mechanism (leg library)</source>
        <translation>Плоский параллельный механизм (библиотека ног)</translation>
    </message>
    <message>
        <source>leg 1: lower limit of the input (P̲RR, RP̲R, П̲RR)</source>
        <translation>нога 1: нижний предел входа (P̲RR, RP̲R, П̲RR)</translation>
    </message>
    <message>
        <source>leg 1: upper limit of the input (P̲RR, RP̲R, П̲RR)</source>
        <translation>нога 1: верхний предел входа (P̲RR, RP̲R, П̲RR)</translation>
    </message>
    <message>
        <source>leg 1: lower limit of the crank angle (R̲RR)</source>
        <translation>нога 1: нижний предел угла кривошипа (R̲RR)</translation>
    </message>
    <message>
        <source>leg 1: upper limit of the crank angle (R̲RR)</source>
        <translation>нога 1: верхний предел угла кривошипа (R̲RR)</translation>
    </message>
    <message>
        <source>leg 2: lower limit of the input (P̲RR, RP̲R, П̲RR)</source>
        <translation>нога 2: нижний предел входа (P̲RR, RP̲R, П̲RR)</translation>
    </message>
    <message>
        <source>leg 2: upper limit of the input (P̲RR, RP̲R, П̲RR)</source>
        <translation>нога 2: верхний предел входа (P̲RR, RP̲R, П̲RR)</translation>
    </message>
    <message>
        <source>leg 2: lower limit of the crank angle (R̲RR)</source>
        <translation>нога 2: нижний предел угла кривошипа (R̲RR)</translation>
    </message>
    <message>
        <source>leg 2: upper limit of the crank angle (R̲RR)</source>
        <translation>нога 2: верхний предел угла кривошипа (R̲RR)</translation>
    </message>
    <message>
        <source>leg 3: lower limit of the input (P̲RR, RP̲R, П̲RR)</source>
        <translation>нога 3: нижний предел входа (P̲RR, RP̲R, П̲RR)</translation>
    </message>
    <message>
        <source>leg 3: upper limit of the input (P̲RR, RP̲R, П̲RR)</source>
        <translation>нога 3: верхний предел входа (P̲RR, RP̲R, П̲RR)</translation>
    </message>
    <message>
        <source>leg 3: lower limit of the crank angle (R̲RR)</source>
        <translation>нога 3: нижний предел угла кривошипа (R̲RR)</translation>
    </message>
    <message>
        <source>leg 3: upper limit of the crank angle (R̲RR)</source>
        <translation>нога 3: верхний предел угла кривошипа (R̲RR)</translation>
    </message>
    <message>
        <source>The drag stops short of the O↔X crossing at x_CD − x_AB = s = %1 mm, where the rods are parallel and the platform can swing: switch the form to go on.</source>
        <translation>Перетаскивание останавливается, не доходя до перехода O↔X при x_CD − x_AB = s = %1 мм, где стержни параллельны и платформа может качаться: чтобы продолжить, переключите форму.</translation>
    </message>
    <message>
        <source>eq. %1 of the П-joint document</source>
        <translation>формула %1 документа о П-шарнире</translation>
    </message>
    <message>
        <source>fig. %1 of the П-joint document</source>
        <translation>рис. %1 документа о П-шарнире</translation>
    </message>
    <message>
        <source>the П-joint document</source>
        <translation>документ о П-шарнире</translation>
    </message>
    <message>
        <source>eq. %1 of the MOMA document</source>
        <translation>формула %1 документа о MOMA</translation>
    </message>
    <message>
        <source>fig. %1 of the MOMA document</source>
        <translation>рис. %1 документа о MOMA</translation>
    </message>
    <message>
        <source>the MOMA document</source>
        <translation>документ о MOMA</translation>
    </message>
    <message>
        <source>eq. %1 of the O-X glide document</source>
        <translation>формула %1 документа об O-X glide</translation>
    </message>
    <message>
        <source>fig. %1 of the O-X glide document</source>
        <translation>рис. %1 документа об O-X glide</translation>
    </message>
    <message>
        <source>the O-X glide document</source>
        <translation>документ об O-X glide</translation>
    </message>
    <message>
        <source>eq. %1 of the four-bar and mobility document</source>
        <translation>формула %1 документа о четырёхзвеннике и подвижности</translation>
    </message>
    <message>
        <source>fig. %1 of the four-bar and mobility document</source>
        <translation>рис. %1 документа о четырёхзвеннике и подвижности</translation>
    </message>
    <message>
        <source>the four-bar and mobility document</source>
        <translation>документ о четырёхзвеннике и подвижности</translation>
    </message>
    <message>
        <source>PKM Studio&apos;s model</source>
        <translation>модель PKM Studio</translation>
    </message>
    <message>
        <source>Input Jacobian of leg 1 (0: inverse singularity)</source>
        <translation>Якобиан входа ноги 1 (0: особое положение обратной кинематики)</translation>
    </message>
    <message>
        <source>Input Jacobian of leg 2 (0: inverse singularity)</source>
        <translation>Якобиан входа ноги 2 (0: особое положение обратной кинематики)</translation>
    </message>
    <message>
        <source>Output Jacobian (0: direct singularity)</source>
        <translation>Якобиан выхода (0: особое положение прямой кинематики)</translation>
    </message>
    <message>
        <source>Determinant of J</source>
        <translation>Определитель J</translation>
    </message>
    <message>
        <source>J = J_q⁻¹·J_x maps lengths to angles, so det J is in rad²/mm², not dimensionless as MOMA&apos;s and the O-X glide&apos;s.</source>
        <translation>J = J_q⁻¹·J_x переводит длины в углы, поэтому det J измеряется в рад²/мм², а не безразмерен, как у MOMA и O-X glide.</translation>
    </message>
    <message>
        <source>Transmission angle between the distal links</source>
        <translation>Угол передачи между шатунами</translation>
    </message>
    <message>
        <source>Distance from the inverse singularities</source>
        <translation>Удаление от особых положений обратной кинематики</translation>
    </message>
    <message>
        <source>Distance from the direct singularities</source>
        <translation>Удаление от особых положений прямой кинематики</translation>
    </message>
    <message>
        <source>Transmission angle γ at C</source>
        <translation>Угол передачи γ в C</translation>
    </message>
    <message>
        <source>Angle at D from DA to DB</source>
        <translation>Угол в D от DA до DB</translation>
    </message>
    <message>
        <source>Rocker angle</source>
        <translation>Угол коромысла</translation>
    </message>
    <message>
        <source>The document takes the arctan of the ratio, which is 180° off wherever CD − BC·cos γ &lt; 0; the program uses atan2.</source>
        <translation>В документе берётся arctg отношения, что даёт ошибку в 180° везде, где CD − BC·cos γ &lt; 0; программа использует atan2.</translation>
    </message>
    <message>
        <source>Angle at B</source>
        <translation>Угол в B</translation>
    </message>
    <message>
        <source>Transfer function dδ/dα</source>
        <translation>Передаточная функция dδ/dα</translation>
    </message>
    <message>
        <source>The document&apos;s (8) and (9) give the rocker&apos;s counter-clockwise rate dθ₃/dt = −dδ/dt; the program&apos;s ω₃ and i₃₁ are their negatives.</source>
        <translation>Формулы (8) и (9) документа дают скорость коромысла против часовой стрелки dθ₃/dt = −dδ/dt; ω₃ и i₃₁ программы — те же величины с обратным знаком.</translation>
    </message>
    <message>
        <source>Rocker angular velocity</source>
        <translation>Угловая скорость коромысла</translation>
    </message>
    <message>
        <source>Rocker angular acceleration at constant ω₁</source>
        <translation>Угловое ускорение коромысла при постоянной ω₁</translation>
    </message>
    <message>
        <source>The document&apos;s (14) agrees with neither sign of the exact second derivative; the program differentiates the loop closure twice.</source>
        <translation>Формула (14) документа не совпадает с точной второй производной ни при каком знаке; программа дважды дифференцирует уравнение замыкания контура.</translation>
    </message>
    <message>
        <source>Input Jacobian (0: inverse singularity)</source>
        <translation>Якобиан входа (0: особое положение обратной кинематики)</translation>
    </message>
    <message>
        <source>Projection on guide %1</source>
        <translation>Проекция на направляющую %1</translation>
    </message>
    <message>
        <source>Reach of link %1</source>
        <translation>Досягаемость звена %1</translation>
    </message>
    <message>
        <source>Inverse kinematics of leg %1</source>
        <translation>Обратная кинематика ноги %1</translation>
    </message>
    <message>
        <source>The program takes B_i² − C_i as l_i² − (a_i × (P − R_i))², the same number without cancelling two large ones.</source>
        <translation>Программа вычисляет B_i² − C_i как l_i² − (a_i × (P − R_i))²: то же число, но без вычитания двух больших чисел.</translation>
    </message>
    <message>
        <source>Direct kinematics: P along Z₁→Z₂</source>
        <translation>Прямая кинематика: P вдоль Z₁→Z₂</translation>
    </message>
    <message>
        <source>The document&apos;s (10–12) divide by x_Z2 − x_Z1 and fail with the slider joints one above the other; the program intersects the circles measured along Z₁→Z₂: P = Z₁ + s·u + σ·h·n, h = √(l₁² − s²).</source>
        <translation>Формулы (10–12) документа делят на x_Z2 − x_Z1 и не работают, когда шарниры ползунов стоят один над другим; программа пересекает окружности, отсчитывая вдоль Z₁→Z₂: P = Z₁ + s·u + σ·h·n, h = √(l₁² − s²).</translation>
    </message>
    <message>
        <source>From J_p·ṗ + J_x·Ṗ = 0 the program&apos;s J is −J_p⁻¹·J_x; the document&apos;s (21) has no minus sign. For the 2×2 J the determinant is the same.</source>
        <translation>Из J_p·ṗ + J_x·Ṗ = 0 в программе J = −J_p⁻¹·J_x; в формуле (21) документа минуса нет. Для матрицы J 2×2 определитель тот же.</translation>
    </message>
    <message>
        <source>Run of a rod along the guides</source>
        <translation>Вынос тяги вдоль направляющих</translation>
    </message>
    <message>
        <source>Inverse kinematics, %1 form</source>
        <translation>Обратная кинематика, форма %1</translation>
    </message>
    <message>
        <source>Direct kinematics, both forms</source>
        <translation>Прямая кинематика, обе формы</translation>
    </message>
    <message>
        <source>The document prints “+ s” in the X form&apos;s direct kinematics, which contradicts its own inverse kinematics; with “− s” both forms return their poses exactly. The sign of x_CD − x_AB − s is the form.</source>
        <translation>В прямой кинематике формы X документ печатает «+ s», что противоречит его же обратной кинематике; с «− s» обе формы точно возвращают свои положения. Знак x_CD − x_AB − s и есть форма.</translation>
    </message>
    <message>
        <source>J = −J_q⁻¹·J_x = [1, y/u₁; 1, y/u₂] from the constraints (x ∓ s/2 − x_i)² + y² − l² = 0; w = 0 (rods perpendicular to the guides or parallel to each other) is singular.</source>
        <translation>J = −J_q⁻¹·J_x = [1, y/u₁; 1, y/u₂] из уравнений связей (x ∓ s/2 − x_i)² + y² − l² = 0; w = 0 (тяги перпендикулярны направляющим или параллельны друг другу) — особое положение.</translation>
    </message>
    <message>
        <source>Condition number of J</source>
        <translation>Число обусловленности J</translation>
    </message>
    <message>
        <source>Inverse kinematics</source>
        <translation>Обратная кинематика</translation>
    </message>
    <message>
        <source>Direct kinematics</source>
        <translation>Прямая кинематика</translation>
    </message>
    <message>
        <source>Transmission angle</source>
        <translation>Угол передачи</translation>
    </message>
    <message>
        <source>Output torque at F_max</source>
        <translation>Выходной момент при F_max</translation>
    </message>
    <message>
        <source>J in mm/rad times F in N gives N·mm; 10⁻³ turns it into N·m.</source>
        <translation>J в мм/рад, умноженный на F в Н, даёт Н·мм; множитель 10⁻³ переводит в Н·м.</translation>
    </message>
    <message>
        <source>Output resolution per motor step</source>
        <translation>Выходное разрешение на шаг двигателя</translation>
    </message>
    <message>
        <source>Motor torque at F_max</source>
        <translation>Момент двигателя при F_max</translation>
    </message>
    <message>
        <source>Table 1 gives no screw efficiency η; the presets assume 0.4.</source>
        <translation>В таблице 1 нет КПД винтовой передачи η; в примерах принято 0,4.</translation>
    </message>
    <message>
        <source>The document&apos;s acceleration (19–20) drops θ̈ from the first term and writes θ̇ where θ̇² belongs; the program uses d̈ = J·θ̈ + (∂J/∂θ)·θ̇², which agrees with the numerical second derivative.</source>
        <translation>В формулах ускорения (19–20) документа в первом члене потеряно θ̈, а вместо θ̇² написано θ̇; программа использует d̈ = J·θ̈ + (∂J/∂θ)·θ̇², что совпадает с численной второй производной.</translation>
    </message>
    <message>
        <source>At the platform&apos;s position %1 the legs would hold it only in the other assembly mode.</source>
        <translation>В положении платформы %1 ноги удержали бы её только в другом режиме сборки.</translation>
    </message>
    <message>
        <source>At the platform&apos;s position %1 leg %2 cannot reach it: its platform point is too far from its base point A%2 for its links.</source>
        <translation>В положении платформы %1 нога %2 не достаёт до неё: её точка платформы слишком далеко от точки основания A%2 для её звеньев.</translation>
    </message>
    <message>
        <source>At the platform&apos;s position %1 leg %2 cannot reach it: its platform point is too near its base point A%2 for its links.</source>
        <translation>В положении платформы %1 нога %2 не достаёт до неё: её точка платформы слишком близко к точке основания A%2 для её звеньев.</translation>
    </message>
    <message>
        <source>At the platform&apos;s position %1 leg %2 cannot reach it: its input would leave its range.</source>
        <translation>В положении платформы %1 нога %2 не достаёт до неё: её вход вышел бы из своего диапазона.</translation>
    </message>
    <message>
        <source>At the platform&apos;s position %1 the input of leg %2 is undetermined.</source>
        <translation>В положении платформы %1 вход ноги %2 не определён.</translation>
    </message>
    <message>
        <source>drag to move the base point A%1 (changes the design)</source>
        <translation>перетащите, чтобы переместить точку основания A%1 (изменяет конструкцию)</translation>
    </message>
    <message>
        <source>drag to move the platform point B%1 (changes the design)</source>
        <translation>перетащите, чтобы переместить точку платформы B%1 (изменяет конструкцию)</translation>
    </message>
    <message>
        <source>Leg %1 (%2): constraint</source>
        <translation>Нога %1 (%2): уравнение связи</translation>
    </message>
    <message>
        <source>Leg %1 (%2): the П-joint&apos;s angle</source>
        <translation>Нога %1 (%2): угол П-шарнира</translation>
    </message>
    <message>
        <source>Leg %1 (%2): the П-joint&apos;s Jacobian</source>
        <translation>Нога %1 (%2): якобиан П-шарнира</translation>
    </message>
    <message>
        <source>The leg&apos;s row of J_x carries this J as a factor, so the П-joint&apos;s own singularity (θ = ±90°) is a direct singularity of the whole mechanism (the П-joint document, section 4).</source>
        <translation>Строка ноги в J_x содержит этот J множителем, поэтому особое положение самого П-шарнира (θ = ±90°) — особое положение прямой кинематики всего механизма (документ о П-шарнире, раздел 4).</translation>
    </message>
    <message>
        <source>Leg %1 (%2): input Jacobian (0: inverse singularity)</source>
        <translation>Нога %1 (%2): якобиан входа (0: особое положение обратной кинематики)</translation>
    </message>
    <message>
        <source>assembly mode 1 (same inputs)</source>
        <translation>режим сборки 1 (те же входы)</translation>
    </message>
    <message>
        <source>assembly mode 2 (same inputs)</source>
        <translation>режим сборки 2 (те же входы)</translation>
    </message>
    <message>
        <source>assembly mode 3 (same inputs)</source>
        <translation>режим сборки 3 (те же входы)</translation>
    </message>
    <message>
        <source>assembly mode 4 (same inputs)</source>
        <translation>режим сборки 4 (те же входы)</translation>
    </message>
    <message>
        <source>assembly mode 5 (same inputs)</source>
        <translation>режим сборки 5 (те же входы)</translation>
    </message>
    <message>
        <source>assembly mode 6 (same inputs)</source>
        <translation>режим сборки 6 (те же входы)</translation>
    </message>
    <message>
        <source>leg 1 stretched (crank and link in line)</source>
        <translation>нога 1 вытянута (кривошип и звено на одной прямой)</translation>
    </message>
    <message>
        <source>leg 1 folded (crank and link in line)</source>
        <translation>нога 1 сложена (кривошип и звено на одной прямой)</translation>
    </message>
    <message>
        <source>leg 2 stretched (crank and link in line)</source>
        <translation>нога 2 вытянута (кривошип и звено на одной прямой)</translation>
    </message>
    <message>
        <source>leg 2 folded (crank and link in line)</source>
        <translation>нога 2 сложена (кривошип и звено на одной прямой)</translation>
    </message>
    <message>
        <source>leg 3 stretched (crank and link in line)</source>
        <translation>нога 3 вытянута (кривошип и звено на одной прямой)</translation>
    </message>
    <message>
        <source>leg 3 folded (crank and link in line)</source>
        <translation>нога 3 сложена (кривошип и звено на одной прямой)</translation>
    </message>
    <message>
        <source>link 3 ⟂ guide 3</source>
        <translation>звено 3 ⟂ направляющей 3</translation>
    </message>
    <message>
        <source>distal lines through one point</source>
        <translation>дистальные прямые через одну точку</translation>
    </message>
    <message>
        <source>actuator 1: maximum force</source>
        <translation>привод 1: наибольшая сила</translation>
    </message>
    <message>
        <source>actuator 2: maximum force</source>
        <translation>привод 2: наибольшая сила</translation>
    </message>
    <message>
        <source>actuator 3: maximum force</source>
        <translation>привод 3: наибольшая сила</translation>
    </message>
    <message>
        <source>actuator 1: maximum speed</source>
        <translation>привод 1: наибольшая скорость</translation>
    </message>
    <message>
        <source>actuator 2: maximum speed</source>
        <translation>привод 2: наибольшая скорость</translation>
    </message>
    <message>
        <source>actuator 3: maximum speed</source>
        <translation>привод 3: наибольшая скорость</translation>
    </message>
    <message>
        <source>actuator 1: step (resolution)</source>
        <translation>привод 1: шаг (разрешение)</translation>
    </message>
    <message>
        <source>actuator 2: step (resolution)</source>
        <translation>привод 2: шаг (разрешение)</translation>
    </message>
    <message>
        <source>actuator 3: step (resolution)</source>
        <translation>привод 3: шаг (разрешение)</translation>
    </message>
    <message>
        <source>actuator 1: axial stiffness</source>
        <translation>привод 1: осевая жёсткость</translation>
    </message>
    <message>
        <source>actuator 2: axial stiffness</source>
        <translation>привод 2: осевая жёсткость</translation>
    </message>
    <message>
        <source>actuator 3: axial stiffness</source>
        <translation>привод 3: осевая жёсткость</translation>
    </message>
    <message>
        <source>actuator 1: maximum torque</source>
        <translation>привод 1: наибольший момент</translation>
    </message>
    <message>
        <source>actuator 2: maximum torque</source>
        <translation>привод 2: наибольший момент</translation>
    </message>
    <message>
        <source>actuator 3: maximum torque</source>
        <translation>привод 3: наибольший момент</translation>
    </message>
    <message>
        <source>actuator 1: maximum angular speed</source>
        <translation>привод 1: наибольшая угловая скорость</translation>
    </message>
    <message>
        <source>actuator 2: maximum angular speed</source>
        <translation>привод 2: наибольшая угловая скорость</translation>
    </message>
    <message>
        <source>actuator 3: maximum angular speed</source>
        <translation>привод 3: наибольшая угловая скорость</translation>
    </message>
    <message>
        <source>actuator 1: angular step (resolution)</source>
        <translation>привод 1: угловой шаг (разрешение)</translation>
    </message>
    <message>
        <source>actuator 2: angular step (resolution)</source>
        <translation>привод 2: угловой шаг (разрешение)</translation>
    </message>
    <message>
        <source>actuator 3: angular step (resolution)</source>
        <translation>привод 3: угловой шаг (разрешение)</translation>
    </message>
    <message>
        <source>actuator 1: torsional stiffness</source>
        <translation>привод 1: крутильная жёсткость</translation>
    </message>
    <message>
        <source>actuator 2: torsional stiffness</source>
        <translation>привод 2: крутильная жёсткость</translation>
    </message>
    <message>
        <source>actuator 3: torsional stiffness</source>
        <translation>привод 3: крутильная жёсткость</translation>
    </message>
    <message>
        <source>largest force in the weakest direction</source>
        <translation>наибольшая сила в самом слабом направлении</translation>
    </message>
    <message>
        <source>largest force in the strongest direction</source>
        <translation>наибольшая сила в самом сильном направлении</translation>
    </message>
    <message>
        <source>largest speed in the slowest direction</source>
        <translation>наибольшая скорость в самом медленном направлении</translation>
    </message>
    <message>
        <source>largest speed in the fastest direction</source>
        <translation>наибольшая скорость в самом быстром направлении</translation>
    </message>
    <message>
        <source>largest error from half a step per actuator</source>
        <translation>наибольшая погрешность от полушага каждого привода</translation>
    </message>
    <message>
        <source>stiffness K = Jᵀ·K_q·J (N/mm, N/rad, N·mm/rad)</source>
        <translation>жёсткость K = Jᵀ·K_q·J (Н/мм, Н/рад, Н·мм/рад)</translation>
    </message>
    <message>
        <source>stiffness K = Jᵀ·K_q·J</source>
        <translation>жёсткость K = Jᵀ·K_q·J</translation>
    </message>
    <message>
        <source>stiffness in the weakest direction</source>
        <translation>жёсткость в самом слабом направлении</translation>
    </message>
    <message>
        <source>measured static stiffness of the whole joint (the document)</source>
        <translation>измеренная статическая жёсткость всего шарнира (по документу)</translation>
    </message>
    <message>
        <source>N/mm</source>
        <translation>Н/мм</translation>
    </message>
    <message>
        <source>axial stiffness of the actuator</source>
        <translation>осевая жёсткость привода</translation>
    </message>
    <message>
        <source>measured static stiffness of the joint</source>
        <translation>измеренная статическая жёсткость шарнира</translation>
    </message>
    <message>
        <source>load: torque on the output link</source>
        <translation>нагрузка: момент на выходном звене</translation>
    </message>
    <message>
        <source>load: force on the platform, x</source>
        <translation>нагрузка: сила на платформе, x</translation>
    </message>
    <message>
        <source>load: force on the platform, y</source>
        <translation>нагрузка: сила на платформе, y</translation>
    </message>
    <message>
        <source>load: moment on the platform</source>
        <translation>нагрузка: момент на платформе</translation>
    </message>
    <message>
        <source>deflection under the load (actuators&apos; compliance)</source>
        <translation>отклонение под нагрузкой (податливость приводов)</translation>
    </message>
    <message>
        <source>deflection of the platform point under the load</source>
        <translation>смещение точки платформы под нагрузкой</translation>
    </message>
    <message>
        <source>length of the deflection under the load</source>
        <translation>величина смещения под нагрузкой</translation>
    </message>
    <message>
        <source>rotation of the platform under the load</source>
        <translation>поворот платформы под нагрузкой</translation>
    </message>
    <message>
        <source>undefined at this singular pose</source>
        <translation>не определено в этой особой позе</translation>
    </message>
    <message>
        <source>cut at the edge of the drawing</source>
        <translation>обрезано по краю чертежа</translation>
    </message>
    <message>
        <source>velocity: 1 mm ≙ %1 mm/s</source>
        <translation>скорость: 1 мм ≙ %1 мм/с</translation>
    </message>
    <message>
        <source>unbounded: the locked actuators do not hold the platform (direct singularity)</source>
        <translation>не ограничено: запертые приводы не удерживают платформу (прямая особенность)</translation>
    </message>
    <message>
        <source>force: 1 mm ≙ %1 N</source>
        <translation>сила: 1 мм ≙ %1 Н</translation>
    </message>
    <message>
        <source>unbounded: a stretched leg holds any force along it (inverse singularity)</source>
        <translation>не ограничено: вытянутая нога держит любую силу вдоль себя (обратная особенность)</translation>
    </message>
    <message>
        <source>The design has no parameter named &apos;%1&apos; to give a tolerance.</source>
        <translation>В конструкции нет параметра «%1», которому можно задать допуск.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; (%2) is not a geometric parameter: tolerances apply to the lengths, positions and angles of the design.</source>
        <translation>«%1» (%2) — не геометрический параметр: допуски задаются для длин, положений и углов конструкции.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is derived from other parameters: give the tolerances of the parameters it is made of.</source>
        <translation>«%1» выводится из других параметров: задайте допуски тех параметров, из которых он получается.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; has no say in this design, so a tolerance on it changes nothing.</source>
        <translation>«%1» не влияет на эту конструкцию, поэтому допуск на него ничего не меняет.</translation>
    </message>
    <message>
        <source>The tolerance of &apos;%1&apos; must be a finite number ≥ 0.</source>
        <translation>Допуск «%1» должен быть конечным числом ≥ 0.</translation>
    </message>
    <message>
        <source>The tolerance ±%2 of &apos;%1&apos; takes it to %3, outside its allowed values.</source>
        <translation>Допуск ±%2 параметра «%1» доводит его до %3, за пределы допустимых значений.</translation>
    </message>
    <message>
        <source>At most %1 tolerances can be given.</source>
        <translation>Можно задать не более %1 допусков.</translation>
    </message>
    <message>
        <source>At a direct singularity the actuators do not hold the platform: the error from the tolerances is unbounded.</source>
        <translation>В особом положении прямой кинематики приводы не удерживают платформу: погрешность от допусков не ограничена.</translation>
    </message>
    <message>
        <source>At a combined singularity the error from the tolerances is undefined.</source>
        <translation>В комбинированном особом положении погрешность от допусков не определена.</translation>
    </message>
    <message>
        <source>The perturbed designs do not assemble at these inputs: the error from the tolerances is undefined here.</source>
        <translation>Изменённые конструкции не собираются при этих входных координатах: погрешность от допусков здесь не определена.</translation>
    </message>
    <message>
        <source>The requirement &apos;%1&apos; cannot be checked: this design declares no actuators.</source>
        <translation>Требование «%1» нельзя проверить: в этой конструкции не заданы приводы.</translation>
    </message>
    <message>
        <source>The requirement &apos;%1&apos; has no comparison: write it as NAME&gt;=VALUE or NAME&lt;=VALUE, for example force_worst&gt;=50.</source>
        <translation>В требовании «%1» нет сравнения: запишите его как ИМЯ&gt;=ЗНАЧЕНИЕ или ИМЯ&lt;=ЗНАЧЕНИЕ, например force_worst&gt;=50.</translation>
    </message>
    <message>
        <source>The requirement &apos;%1&apos; names no single capability value; it may name %2.</source>
        <translation>Требование «%1» не называет ни одной отдельной величины возможностей привода; допустимы %2.</translation>
    </message>
    <message>
        <source>The requirement &apos;%1&apos; does not end in a finite number.</source>
        <translation>Требование «%1» не заканчивается конечным числом.</translation>
    </message>
    <message>
        <source>worst-case error from the tolerances</source>
        <translation>наибольшая ошибка от допусков</translation>
    </message>
    <message>
        <source>near an inverse singularity: an actuator moves the platform less than 1/1000 of what it does at the home pose</source>
        <translation>вблизи особого положения обратной кинематики: привод перемещает платформу менее чем на 1/1000 того, что в исходном положении</translation>
    </message>
    <message>
        <source>near a direct singularity: an actuator moves the platform more than 1000 times what it does at the home pose</source>
        <translation>вблизи особого положения прямой кинематики: привод перемещает платформу более чем в 1000 раз сильнее, чем в исходном положении</translation>
    </message>
    <message>
        <source>near a combined singularity: one actuator moves the platform less than 1/1000, another more than 1000 times what it does at the home pose</source>
        <translation>вблизи комбинированного особого положения: один привод перемещает платформу менее чем на 1/1000, другой более чем в 1000 раз сильнее, чем в исходном положении</translation>
    </message>
    <message>
        <source>mm³</source>
        <translation>мм³</translation>
    </message>
    <message>
        <source>mm³/rad</source>
        <translation>мм³/рад</translation>
    </message>
    <message>
        <source>mm⁴/rad</source>
        <translation>мм⁴/рад</translation>
    </message>
    <message>
        <source>mm⁵/rad</source>
        <translation>мм⁵/рад</translation>
    </message>
    <message>
        <source>mm⁴/rad²</source>
        <translation>мм⁴/рад²</translation>
    </message>
    <message>
        <source>mm⁵/rad²</source>
        <translation>мм⁵/рад²</translation>
    </message>
    <message>
        <source>mm⁶/rad²</source>
        <translation>мм⁶/рад²</translation>
    </message>
    <message>
        <source>mm⁶/rad³</source>
        <translation>мм⁶/рад³</translation>
    </message>
    <message>
        <source>mm⁷/rad³</source>
        <translation>мм⁷/рад³</translation>
    </message>
    <message>
        <source>C cannot reach %1 in this assembly mode (%2): it would cross the line BD, where the distal links are in line (a direct singularity); switch to the other assembly mode to go on.</source>
        <translation>C не может достичь точки %1 в этом варианте сборки (%2): она пересекла бы прямую BD, на которой шатуны лежат на одной линии (особое положение прямой кинематики); чтобы продолжить, переключитесь на другой вариант сборки.</translation>
    </message>
    <message>
        <source>The numbers put in are rounded as shown; every result is worked out from the unrounded values, so the last digits of a result can differ from one worked out by hand from the shown numbers.</source>
        <translation>Подставленные числа округлены до показанных знаков; каждый результат вычислен по неокруглённым значениям, поэтому его последние цифры могут отличаться от полученных вручную по показанным числам.</translation>
    </message>
    <message>
        <source>constant orientation</source>
        <translation>постоянная ориентация</translation>
    </message>
    <message>
        <source>free body</source>
        <translation>свободное тело</translation>
    </message>
    <message>
        <source>°/s</source>
        <translation>°/с</translation>
    </message>
    <message>
        <source>platform: 2 DOF as a point or with constant orientation, 3 as a free body</source>
        <translation>платформа: 2 степени свободы как точка или с постоянной ориентацией, 3 как свободное тело</translation>
    </message>
    <message>
        <source>leg 1: type (the actuated joint underlined)</source>
        <translation>нога 1: тип (приводной шарнир подчёркнут)</translation>
    </message>
    <message>
        <source>leg 2: type (the actuated joint underlined)</source>
        <translation>нога 2: тип (приводной шарнир подчёркнут)</translation>
    </message>
    <message>
        <source>leg 3: type (the actuated joint underlined)</source>
        <translation>нога 3: тип (приводной шарнир подчёркнут)</translation>
    </message>
    <message>
        <source>At these inputs the platform would have left its assembly mode: it ends on the way, where it meets another at a direct singularity. Switch the assembly mode to go on.</source>
        <translation>При этих входах платформа покинула бы свой режим сборки: он заканчивается по пути, где встречается с другим в особом положении прямой кинематики. Чтобы продолжить, переключите режим сборки.</translation>
    </message>
    <message>
        <source>leg 1: working mode, the elbow left or right of A₁→P₁ (P̲RR: left, the root q = B + √…)</source>
        <translation>нога 1: рабочий режим, локоть слева или справа от A₁→P₁ (P̲RR: слева — корень q = B + √…)</translation>
    </message>
    <message>
        <source>leg 2: working mode, the elbow left or right of A₂→P₂ (P̲RR: left, the root q = B + √…)</source>
        <translation>нога 2: рабочий режим, локоть слева или справа от A₂→P₂ (P̲RR: слева — корень q = B + √…)</translation>
    </message>
    <message>
        <source>leg 3: working mode, the elbow left or right of A₃→P₃ (P̲RR: left, the root q = B + √…)</source>
        <translation>нога 3: рабочий режим, локоть слева или справа от A₃→P₃ (P̲RR: слева — корень q = B + √…)</translation>
    </message>
    <message>
        <source>Jacobian, its own determinant (one input, one output)</source>
        <translation>Якобиан, он же свой определитель (один вход, один выход)</translation>
    </message>
    <message>
        <source>J maps the rocker&apos;s rate onto the crank&apos;s, α̇ = J·δ̇, so J = 1/i₃₁.</source>
        <translation>J переводит скорость коромысла в скорость кривошипа, α̇ = J·δ̇, поэтому J = 1/i₃₁.</translation>
    </message>
    <message>
        <source>behind</source>
        <translation>позади</translation>
    </message>
    <message>
        <source>ahead</source>
        <translation>впереди</translation>
    </message>
    <message>
        <source>working mode of leg 1: the platform behind slider Z₁ along guide 1 or ahead of it</source>
        <translation>рабочий режим ноги 1: платформа позади ползуна Z₁ вдоль направляющей 1 или впереди него</translation>
    </message>
    <message>
        <source>working mode of leg 2: the platform behind slider Z₂ along guide 2 or ahead of it</source>
        <translation>рабочий режим ноги 2: платформа позади ползуна Z₂ вдоль направляющей 2 или впереди него</translation>
    </message>
    <message>
        <source>assembly mode: the platform left or right of Z₁→Z₂</source>
        <translation>вариант сборки: платформа слева или справа от Z₁→Z₂</translation>
    </message>
    <message>
        <source>u₁ = x − s/2 − x_AB and u₂ = x + s/2 − x_CD are the rods&apos; runs along the guides, w and −w in the O form, −w and w in the X form.</source>
        <translation>u₁ = x − s/2 − x_AB и u₂ = x + s/2 − x_CD — выносы тяг вдоль направляющих: w и −w в форме O, −w и w в форме X.</translation>
    </message>
    <message>
        <source>Jacobian J = ∂d/∂θ</source>
        <translation>Якобиан J = ∂d/∂θ</translation>
    </message>
    <message>
        <source>Output speed at the diagonal&apos;s top speed</source>
        <translation>Скорость выхода при наибольшей скорости диагонали</translation>
    </message>
    <message>
        <source>Derivative of J, for the diagonal&apos;s acceleration</source>
        <translation>Производная J, для ускорения диагонали</translation>
    </message>
    <message>
        <source>J_i is the П-joint&apos;s Jacobian ∂d/∂θ of a П̲RR leg and 1 for the other leg types; C_i is A_i for an RP̲R leg.</source>
        <translation>J_i — якобиан П-шарнира ∂d/∂θ для ноги П̲RR и 1 для ног других типов; C_i — это A_i для ноги RP̲R.</translation>
    </message>
    <message>
        <source>C_i is the centre of leg i&apos;s circle: the elbow, the slider joint, or A_i for an RP̲R leg.</source>
        <translation>C_i — центр окружности ноги i: локоть, шарнир ползуна или A_i для ноги RP̲R.</translation>
    </message>
</context>
<context>
    <name>pkm::Animation</name>
    <message>
        <source>The animation needs a pose variable of the mechanism.</source>
        <translation>Для анимации нужна переменная положения механизма.</translation>
    </message>
    <message>
        <source>An animation has %1 to %2 frames, not %3.</source>
        <translation>Анимация должна содержать от %1 до %2 кадров, а не %3.</translation>
    </message>
    <message>
        <source>Frame %1 (%2 = %3): %4</source>
        <translation>Кадр %1 (%2 = %3): %4</translation>
    </message>
    <message>
        <source>The animation was cancelled.</source>
        <translation>Анимация отменена.</translation>
    </message>
    <message>
        <source>A video file&apos;s name ends in .mp4 or .webm: %1.</source>
        <translation>Имя видеофайла должно оканчиваться на .mp4 или .webm: %1.</translation>
    </message>
    <message>
        <source>An animation draws at most %1 million pixels (frames × width × height); %2 frames of %3 × %4 would be %5 million: take fewer steps or a smaller size.</source>
        <translation>Анимация рисует не более %1 миллионов пикселей (кадры × ширина × высота); %2 кадров размером %3 × %4 дали бы %5 миллионов: возьмите меньше шагов или меньший размер.</translation>
    </message>
</context>
<context>
    <name>pkm::AnimationDialog</name>
    <message>
        <source>Beside the view</source>
        <translation>Рядом с видом</translation>
    </message>
    <message>
        <source>Each frame shows the mechanism at the left and this plot at the right, its cursor following the pose.</source>
        <translation>Каждый кадр показывает механизм слева и этот график справа; курсор графика следует за положением.</translation>
    </message>
    <message>
        <source>Nothing</source>
        <translation>Ничего</translation>
    </message>
    <message>
        <source>The plot on screen: %1</source>
        <translation>График на экране: %1</translation>
    </message>
    <message>
        <source>%1 against %2 — %3</source>
        <translation>%1 от %2 — %3</translation>
    </message>
    <message>
        <source>Export Animation</source>
        <translation>Экспорт анимации</translation>
    </message>
    <message>
        <source>Move</source>
        <translation>Переменная</translation>
    </message>
    <message>
        <source>From</source>
        <translation>От</translation>
    </message>
    <message>
        <source>To</source>
        <translation>До</translation>
    </message>
    <message>
        <source>Frames</source>
        <translation>Число кадров</translation>
    </message>
    <message>
        <source> ms per frame</source>
        <translation> мс на кадр</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Скорость</translation>
    </message>
    <message>
        <source>%1 × %2 pixels</source>
        <translation>%1 × %2 пикс.</translation>
    </message>
    <message>
        <source>Size</source>
        <translation>Размер</translation>
    </message>
    <message>
        <source>Play back to the start (a smooth loop)</source>
        <translation>Возвращаться к началу (плавный цикл)</translation>
    </message>
    <message>
        <source>Export…</source>
        <translation>Экспорт…</translation>
    </message>
    <message numerus="yes">
        <source>Drawing %n frame(s)…</source>
        <translation>
            <numerusform>Отрисовка %n кадра…</numerusform>
            <numerusform>Отрисовка %n кадров…</numerusform>
            <numerusform>Отрисовка %n кадров…</numerusform>
        </translation>
    </message>
    <message>
        <source>Cannot write %1: %2.</source>
        <translation>Не удаётся записать %1: %2.</translation>
    </message>
    <message>
        <source>Animation export cancelled.</source>
        <translation>Экспорт анимации отменён.</translation>
    </message>
    <message>
        <source>Wrote %1 (%2 kB)</source>
        <translation>Записан файл %1 (%2 КБ)</translation>
    </message>
    <message>
        <source>Animated GIF</source>
        <translation>Анимированный GIF</translation>
    </message>
    <message>
        <source>MP4 video (H.264, 30 frames/s)</source>
        <translation>Видео MP4 (H.264, 30 кадров/с)</translation>
    </message>
    <message>
        <source>WebM video (VP9, 30 frames/s)</source>
        <translation>Видео WebM (VP9, 30 кадров/с)</translation>
    </message>
    <message>
        <source>Format</source>
        <translation>Формат</translation>
    </message>
    <message>
        <source>A GIF&apos;s speed; a video plays 30 frames per second.</source>
        <translation>Скорость GIF; видео воспроизводится с частотой 30 кадров в секунду.</translation>
    </message>
    <message>
        <source>Animated GIF (*.gif)</source>
        <translation>Анимированный GIF (*.gif)</translation>
    </message>
    <message>
        <source>MP4 video (*.mp4)</source>
        <translation>Видео MP4 (*.mp4)</translation>
    </message>
    <message>
        <source>WebM video (*.webm)</source>
        <translation>Видео WebM (*.webm)</translation>
    </message>
    <message numerus="yes">
        <source>Encoding %n frame(s)…</source>
        <translation>
            <numerusform>Кодирование %n кадра…</numerusform>
            <numerusform>Кодирование %n кадров…</numerusform>
            <numerusform>Кодирование %n кадров…</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>pkm::AnimationPlot</name>
    <message>
        <source>%1 against %2</source>
        <translation>%1 (по оси абсцисс: %2)</translation>
    </message>
    <message>
        <source>— (undefined at this singular pose)</source>
        <translation>— (не определено в этом особом положении)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a quantity the %2 can plot; it has %3</source>
        <translation>«%1» — не величина, которую %2 может построить; есть: %3</translation>
    </message>
</context>
<context>
    <name>pkm::BackgroundTask</name>
    <message>
        <source>Cancel</source>
        <translation>Отмена</translation>
    </message>
</context>
<context>
    <name>pkm::DesignPanel</name>
    <message>
        <source>Geometry</source>
        <translation>Геометрия</translation>
    </message>
    <message>
        <source>Motion range</source>
        <translation>Диапазон движения</translation>
    </message>
    <message>
        <source>Actuator</source>
        <translation>Привод</translation>
    </message>
    <message>
        <source>Motor body (drawing)</source>
        <translation>Корпус двигателя (чертёж)</translation>
    </message>
    <message>
        <source>Modes</source>
        <translation>Режимы</translation>
    </message>
    <message>
        <source>less</source>
        <translation>свернуть</translation>
    </message>
    <message>
        <source>more…</source>
        <translation>подробнее…</translation>
    </message>
    <message>
        <source>greater than %1</source>
        <translation>больше %1</translation>
    </message>
    <message>
        <source>between %1 and %2</source>
        <translation>от %1 до %2</translation>
    </message>
    <message>
        <source>The last valid design is kept.</source>
        <translation>Сохраняется последняя допустимая конструкция.</translation>
    </message>
    <message>
        <source>%1 (%2): &apos;%3&apos; is not a number.</source>
        <translation>%1 (%2): «%3» — не число.</translation>
    </message>
    <message>
        <source>%1: %2. Up/Down or the mouse wheel step by %3.</source>
        <translation>%1: %2. Клавиши ↑/↓ или колесо мыши меняют значение с шагом %3.</translation>
    </message>
    <message>
        <source>Name in design files and on the command line: %1</source>
        <translation>Имя в файлах конструкций и в командной строке: %1</translation>
    </message>
</context>
<context>
    <name>pkm::DesignSession</name>
    <message>
        <source>Untitled design</source>
        <translation>Конструкция без названия</translation>
    </message>
    <message>
        <source>Cannot write %1: %2.</source>
        <translation>Не удаётся записать %1: %2.</translation>
    </message>
</context>
<context>
    <name>pkm::Document</name>
    <message>
        <source>Open %1</source>
        <translation>Открыть %1</translation>
    </message>
    <message>
        <source>Switch to %1</source>
        <translation>Переход: %1</translation>
    </message>
    <message>
        <source>%1 stops at its upper limit %2: %3.</source>
        <translation>%1 упирается в верхнюю границу %2: %3.</translation>
    </message>
    <message>
        <source>%1 stops at its lower limit %2: %3.</source>
        <translation>%1 упирается в нижнюю границу %2: %3.</translation>
    </message>
    <message>
        <source>%1 stops at its upper limit %2 (design range).</source>
        <translation>%1 упирается в верхнюю границу %2 (заданный диапазон).</translation>
    </message>
    <message>
        <source>%1 stops at its lower limit %2 (design range).</source>
        <translation>%1 упирается в нижнюю границу %2 (заданный диапазон).</translation>
    </message>
    <message>
        <source>Close to a singular pose: small input steps make large output jumps.</source>
        <translation>Близко к особому положению: малые шаги на входе дают большие скачки на выходе.</translation>
    </message>
    <message>
        <source>That mode is not available at this pose.</source>
        <translation>Этот режим недоступен в данном положении.</translation>
    </message>
    <message>
        <source>Singular pose (inverse): the mechanism cannot be driven here.</source>
        <translation>Особое положение (обратной кинематики): здесь механизмом нельзя управлять.</translation>
    </message>
    <message>
        <source>Singular pose (direct): the mechanism cannot be driven here.</source>
        <translation>Особое положение (прямой кинематики): здесь механизмом нельзя управлять.</translation>
    </message>
    <message>
        <source>Singular pose (combined): the mechanism cannot be driven here.</source>
        <translation>Особое положение (комбинированное): здесь механизмом нельзя управлять.</translation>
    </message>
    <message>
        <source>A design keeps at most %1 bookmarks: remove one first.</source>
        <translation>Конструкция хранит не более %1 закладок: сначала удалите одну.</translation>
    </message>
    <message>
        <source>Add bookmark “%1”</source>
        <translation>Добавить закладку «%1»</translation>
    </message>
    <message>
        <source>There is no bookmark %1.</source>
        <translation>Закладки %1 нет.</translation>
    </message>
    <message>
        <source>Remove bookmark “%1”</source>
        <translation>Удалить закладку «%1»</translation>
    </message>
    <message>
        <source>Bookmark “%1”: %2</source>
        <translation>Закладка «%1»: %2</translation>
    </message>
    <message>
        <source>New design from template %1</source>
        <translation>Новая конструкция по шаблону %1</translation>
    </message>
    <message>
        <source>Move %1</source>
        <translation>Переместить %1</translation>
    </message>
    <message>
        <source>A design keeps at most %1 tolerances.</source>
        <translation>Конструкция хранит не более %1 допусков.</translation>
    </message>
    <message>
        <source>Change tolerance of %1</source>
        <translation>Изменить допуск %1</translation>
    </message>
    <message>
        <source>Clear tolerances</source>
        <translation>Удалить допуски</translation>
    </message>
    <message>
        <source>Change requirements</source>
        <translation>Изменить требования</translation>
    </message>
</context>
<context>
    <name>pkm::EquationsPanel</name>
    <message>
        <source>This kind lists no equations.</source>
        <translation>Для этого вида механизма уравнения не заданы.</translation>
    </message>
</context>
<context>
    <name>pkm::FormWorkspaceView</name>
    <message>
        <source>x (mm)</source>
        <translation>x (мм)</translation>
    </message>
    <message>
        <source>y (mm)</source>
        <translation>y (мм)</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>union, outlined: %1</source>
        <translation>объединение (контур): %1</translation>
    </message>
    <message>
        <source>Areas of the forms: exact (closed form). Union: counted on a %1 × %2 grid.</source>
        <translation>Площади форм — точные (по формулам). Объединение — подсчитано на сетке %1 × %2.</translation>
    </message>
    <message>
        <source>Areas counted on a %1 × %2 grid.</source>
        <translation>Площади подсчитаны на сетке %1 × %2.</translation>
    </message>
</context>
<context>
    <name>pkm::FourBarPanel</name>
    <message>
        <source>Link lengths</source>
        <translation>Длины звеньев</translation>
    </message>
    <message>
        <source>AB crank</source>
        <translation>AB кривошип</translation>
    </message>
    <message>
        <source>BC coupler</source>
        <translation>BC шатун</translation>
    </message>
    <message>
        <source>CD rocker</source>
        <translation>CD коромысло</translation>
    </message>
    <message>
        <source>AD ground</source>
        <translation>AD стойка</translation>
    </message>
    <message>
        <source>Transmission angle γ at C</source>
        <translation>Угол передачи γ в C</translation>
    </message>
    <message>
        <source>The crank drives the rocker well when γ stays between %1° and %2°.</source>
        <translation>Кривошип хорошо передаёт движение коромыслу, пока γ остаётся в пределах от %1° до %2°.</translation>
    </message>
    <message>
        <source>The last valid design is kept.</source>
        <translation>Сохраняется последняя допустимая конструкция.</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>the crank AB, the shortest link, turns fully; the rocker CD swings.</source>
        <translation>кривошип AB, самое короткое звено, совершает полный оборот; коромысло CD качается.</translation>
    </message>
    <message>
        <source>the rocker CD, the shortest link, could turn fully; the crank AB only swings.</source>
        <translation>коромысло CD, самое короткое звено, могло бы совершать полный оборот; кривошип AB только качается.</translation>
    </message>
    <message>
        <source>the ground AD is the shortest link: the crank and the rocker both turn fully (drag link).</source>
        <translation>стойка AD — самое короткое звено: и кривошип, и коромысло совершают полный оборот (двухкривошипный механизм).</translation>
    </message>
    <message>
        <source>the coupler BC is the shortest link: the crank and the rocker only swing.</source>
        <translation>шатун BC — самое короткое звено: кривошип и коромысло только качаются.</translation>
    </message>
    <message>
        <source>non-Grashof: no link turns fully.</source>
        <translation>условие Грасгофа не выполнено: ни одно звено не совершает полного оборота.</translation>
    </message>
    <message>
        <source>the links can fold flat in line, where the open and crossed branches meet.</source>
        <translation>звенья могут сложиться в одну линию — там встречаются открытая и скрещенная ветви.</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;: s + l = %2 %3 p + q = %4; %5</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;: s + l = %2 %3 p + q = %4; %5</translation>
    </message>
    <message>
        <source>&lt;b&gt;α&lt;/b&gt;: the crank turns fully, %1 … %2</source>
        <translation>&lt;b&gt;α&lt;/b&gt;: кривошип совершает полный оборот, %1 … %2</translation>
    </message>
    <message>
        <source>&lt;b&gt;α&lt;/b&gt; assembles from %1 to %2 only: at the ends the coupler and the rocker are in line (dead points)</source>
        <translation>&lt;b&gt;α&lt;/b&gt;: механизм собирается только в пределах от %1 до %2; на концах шатун и коромысло лежат на одной прямой (мёртвые точки)</translation>
    </message>
    <message>
        <source>&lt;span style=&apos;color:#b3261e&apos;&gt;over the motion %1° … %2°: enters the poor band&lt;/span&gt;</source>
        <translation>&lt;span style=&apos;color:#b3261e&apos;&gt;за цикл движения %1° … %2°: заходит в зону плохой передачи&lt;/span&gt;</translation>
    </message>
    <message>
        <source>over the motion %1° … %2°: inside %3° … %4°</source>
        <translation>за цикл движения %1° … %2°: в пределах %3° … %4°</translation>
    </message>
    <message>
        <source>%1 — poor: %2</source>
        <translation>%1 — плохая передача: %2</translation>
    </message>
    <message>
        <source>below %1°</source>
        <translation>ниже %1°</translation>
    </message>
    <message>
        <source>above %1°</source>
        <translation>выше %1°</translation>
    </message>
    <message>
        <source>α stops at its upper limit: %1.</source>
        <translation>α упирается в верхнюю границу: %1.</translation>
    </message>
    <message>
        <source>α stops at its lower limit: %1.</source>
        <translation>α упирается в нижнюю границу: %1.</translation>
    </message>
    <message>
        <source>Crank-rocker</source>
        <translation>Кривошипно-коромысловый механизм</translation>
    </message>
    <message>
        <source>Rocker-crank</source>
        <translation>Коромыслово-кривошипный механизм</translation>
    </message>
    <message>
        <source>Double-crank</source>
        <translation>Двухкривошипный механизм</translation>
    </message>
    <message>
        <source>Double-rocker</source>
        <translation>Двухкоромысловый механизм</translation>
    </message>
    <message>
        <source>Triple-rocker</source>
        <translation>Трёхкоромысловый механизм</translation>
    </message>
    <message>
        <source>Change-point</source>
        <translation>Граничный случай Грасгофа</translation>
    </message>
    <message>
        <source>%1. &lt;b&gt;δ&lt;/b&gt; swings over %2 … %3 (crossed branch).</source>
        <translation>%1. &lt;b&gt;δ&lt;/b&gt; изменяется в пределах %2 … %3 (скрещенная ветвь).</translation>
    </message>
    <message>
        <source>%1. &lt;b&gt;δ&lt;/b&gt; swings over %2 … %3 (open branch).</source>
        <translation>%1. &lt;b&gt;δ&lt;/b&gt; изменяется в пределах %2 … %3 (открытая ветвь).</translation>
    </message>
</context>
<context>
    <name>pkm::FourBarPlots</name>
    <message>
        <source>δ(α) — fig. 4</source>
        <translation>δ(α) — рис. 4</translation>
    </message>
    <message>
        <source>ω₃, ε₃ — fig. 6</source>
        <translation>ω₃, ε₃ — рис. 6</translation>
    </message>
    <message>
        <source>δ vs AB — fig. 5</source>
        <translation>δ от AB — рис. 5</translation>
    </message>
    <message>
        <source>The rocker angle δ over the crank&apos;s range (click to set α)</source>
        <translation>Угол коромысла δ во всём диапазоне кривошипа (щелчок задаёт α)</translation>
    </message>
    <message>
        <source>The rocker&apos;s angular velocity and acceleration at constant ω₁ (click to set α)</source>
        <translation>Угловая скорость и угловое ускорение коромысла при постоянной ω₁ (щелчок задаёт α)</translation>
    </message>
    <message>
        <source>The transmission angle at C; shaded where the crank drives the rocker poorly</source>
        <translation>Угол передачи в шарнире C; затенены области, где кривошип плохо приводит коромысло</translation>
    </message>
    <message>
        <source>δ at the current α as the crank length AB changes, the other links fixed</source>
        <translation>δ при текущем α в зависимости от длины кривошипа AB, остальные звенья неизменны</translation>
    </message>
    <message>
        <source>Click or drag to set the crank angle α</source>
        <translation>Щёлкните или протяните, чтобы задать угол кривошипа α</translation>
    </message>
    <message>
        <source>AB/BC/CD/AD = %1/%2/%3/%4 mm, %5 branch</source>
        <translation>AB/BC/CD/AD = %1/%2/%3/%4 мм, %5 ветвь</translation>
    </message>
    <message>
        <source>Fig. 4 — rocker angle δ(α)</source>
        <translation>Рис. 4 — угол коромысла δ(α)</translation>
    </message>
    <message>
        <source>Fig. 6 — rocker angular velocity ω₃ = dδ/dt</source>
        <translation>Рис. 6 — угловая скорость коромысла ω₃ = dδ/dt</translation>
    </message>
    <message>
        <source>Fig. 6 — rocker angular acceleration ε₃ = d²δ/dt²</source>
        <translation>Рис. 6 — угловое ускорение коромысла ε₃ = d²δ/dt²</translation>
    </message>
    <message>
        <source>Transmission angle γ(α), (5)</source>
        <translation>Угол передачи γ(α), (5)</translation>
    </message>
    <message>
        <source>Fig. 5 — rocker angle δ against the crank length AB</source>
        <translation>Рис. 5 — угол коромысла δ в зависимости от длины кривошипа AB</translation>
    </message>
    <message>
        <source>ω₁ = %1 rad/s constant; exact (the document&apos;s (8) has the opposite sign)</source>
        <translation>ω₁ = %1 рад/с = const; точно (в формуле (8) статьи знак противоположный)</translation>
    </message>
    <message>
        <source>ω₁ = %1 rad/s constant; exact (not the document&apos;s (14))</source>
        <translation>ω₁ = %1 рад/с = const; точно (не по формуле (14) статьи)</translation>
    </message>
    <message>
        <source>at α = %1°; BC, CD, AD fixed</source>
        <translation>при α = %1°; BC, CD, AD неизменны</translation>
    </message>
    <message>
        <source>ω₃ (rad/s)</source>
        <translation>ω₃ (рад/с)</translation>
    </message>
    <message>
        <source>ε₃ (rad/s²)</source>
        <translation>ε₃ (рад/с²)</translation>
    </message>
    <message>
        <source>crank length AB (mm)</source>
        <translation>длина кривошипа AB (мм)</translation>
    </message>
    <message>
        <source>crank angle α (°)</source>
        <translation>угол кривошипа α (°)</translation>
    </message>
    <message>
        <source>poor transmission: |γ| &lt; %1° or &gt; %2°</source>
        <translation>плохая передача: |γ| &lt; %1° или &gt; %2°</translation>
    </message>
    <message>
        <source>δ at α = %1°</source>
        <translation>δ при α = %1°</translation>
    </message>
    <message>
        <source>largest AB that assembles: %1 mm</source>
        <translation>наибольшая собираемая AB: %1 мм</translation>
    </message>
    <message>
        <source>ω₃ = %1 rad/s</source>
        <translation>ω₃ = %1 рад/с</translation>
    </message>
    <message>
        <source>ε₃ = %1 rad/s²</source>
        <translation>ε₃ = %1 рад/с²</translation>
    </message>
    <message>
        <source>AB = %1 mm, δ = %2°</source>
        <translation>AB = %1 мм, δ = %2°</translation>
    </message>
    <message>
        <source>%1 → %2∞: dead point</source>
        <translation>%1 → %2∞: мёртвая точка</translation>
    </message>
    <message>
        <source>no pose</source>
        <translation>положения нет</translation>
    </message>
    <message>
        <source>crossed</source>
        <comment>branch</comment>
        <translation>скрещенная</translation>
    </message>
    <message>
        <source>open</source>
        <comment>branch</comment>
        <translation>открытая</translation>
    </message>
</context>
<context>
    <name>pkm::GifWriter</name>
    <message>
        <source>An animation needs at least one frame.</source>
        <translation>Для анимации нужен хотя бы один кадр.</translation>
    </message>
    <message>
        <source>A GIF frame must be 1 to 65535 pixels on each side.</source>
        <translation>Кадр GIF должен иметь от 1 до 65535 пикселей по каждой стороне.</translation>
    </message>
    <message>
        <source>All frames of a GIF must have the same size.</source>
        <translation>Все кадры GIF должны быть одного размера.</translation>
    </message>
    <message>
        <source>giflib: out of memory.</source>
        <translation>giflib: недостаточно памяти.</translation>
    </message>
    <message>
        <source>giflib could not reduce a frame to 256 colours.</source>
        <translation>giflib не удалось свести кадр к 256 цветам.</translation>
    </message>
</context>
<context>
    <name>pkm::GuideWindow</name>
    <message>
        <source>PKM Studio User Guide</source>
        <translation>Руководство пользователя PKM Studio</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Назад</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>В начало</translation>
    </message>
    <message>
        <source>The start of the guide</source>
        <translation>Начало руководства</translation>
    </message>
    <message>
        <source>&amp;Find:</source>
        <translation>&amp;Найти:</translation>
    </message>
    <message>
        <source>a word in the guide (Ctrl+F)</source>
        <translation>слово в руководстве (Ctrl+F)</translation>
    </message>
    <message>
        <source>Previous</source>
        <translation>Предыдущее</translation>
    </message>
    <message>
        <source>Next</source>
        <translation>Следующее</translation>
    </message>
    <message>
        <source>Not found</source>
        <translation>Не найдено</translation>
    </message>
</context>
<context>
    <name>pkm::LinkageView</name>
    <message>
        <source>Click to switch to: %1</source>
        <translation>Щёлкните, чтобы переключиться: %1</translation>
    </message>
    <message>
        <source>this pose</source>
        <translation>это положение</translation>
    </message>
</context>
<context>
    <name>pkm::LinkageView3D</name>
    <message>
        <source>3D view unavailable: OpenGL 3.3 could not be started.</source>
        <translation>3D-вид недоступен: не удалось запустить OpenGL 3.3.</translation>
    </message>
    <message>
        <source>A picture needs a size of at least one pixel.</source>
        <translation>Размер изображения должен быть не меньше одного пикселя.</translation>
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
        <translation>Механизм в 3D: перетаскивание — поворот, правой кнопкой — сдвиг, колесо — масштаб</translation>
    </message>
    <message>
        <source>Design</source>
        <translation>Конструкция</translation>
    </message>
    <message>
        <source>Mobility</source>
        <translation>Подвижность</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Файл</translation>
    </message>
    <message>
        <source>&amp;Open Design…</source>
        <translation>&amp;Открыть конструкцию…</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>&amp;Недавние</translation>
    </message>
    <message>
        <source>&amp;Save Design</source>
        <translation>&amp;Сохранить конструкцию</translation>
    </message>
    <message>
        <source>Save Design &amp;As…</source>
        <translation>Сохранить конструкцию &amp;как…</translation>
    </message>
    <message>
        <source>Export &amp;Drawing (DXF)…</source>
        <translation>Экспорт &amp;чертежа (DXF)…</translation>
    </message>
    <message>
        <source>Export &amp;Parameter Sheet…</source>
        <translation>Экспорт &amp;листа параметров…</translation>
    </message>
    <message>
        <source>Save 2D &amp;View Picture…</source>
        <translation>Сохранить изображение &amp;2D-вида…</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>В&amp;ыход</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Правка</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Отменить</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Повторить</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Отменить</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Повторить</translation>
    </message>
    <message>
        <source>&amp;Presets</source>
        <translation>&amp;Примеры</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Вид</translation>
    </message>
    <message>
        <source>&amp;Fit Mechanism</source>
        <translation>&amp;Вписать механизм</translation>
    </message>
    <message>
        <source>Zoom &amp;In</source>
        <translation>У&amp;величить</translation>
    </message>
    <message>
        <source>Zoom &amp;Out</source>
        <translation>У&amp;меньшить</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Справка</translation>
    </message>
    <message>
        <source>&amp;About PKM Studio</source>
        <translation>&amp;О программе PKM Studio</translation>
    </message>
    <message>
        <source>Switched to %1.</source>
        <translation>Переключено: %1.</translation>
    </message>
    <message>
        <source>Open Design</source>
        <translation>Открыть конструкцию</translation>
    </message>
    <message>
        <source>PKM Studio designs (*.pkm.json);;All files (*)</source>
        <translation>Конструкции PKM Studio (*.pkm.json);;Все файлы (*)</translation>
    </message>
    <message>
        <source>Save Design</source>
        <translation>Сохранение конструкции</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>Сохранено: %1</translation>
    </message>
    <message>
        <source>Save Design As</source>
        <translation>Сохранить конструкцию как</translation>
    </message>
    <message>
        <source>PKM Studio designs (*.pkm.json)</source>
        <translation>Конструкции PKM Studio (*.pkm.json)</translation>
    </message>
    <message>
        <source>Unsaved Changes</source>
        <translation>Несохранённые изменения</translation>
    </message>
    <message>
        <source>The design “%1” has changes that are not saved. Save them?</source>
        <translation>В конструкции «%1» есть несохранённые изменения. Сохранить их?</translation>
    </message>
    <message>
        <source>Recover Design</source>
        <translation>Восстановление конструкции</translation>
    </message>
    <message>
        <source>PKM Studio closed unexpectedly while “%1” had unsaved changes (autosaved %2). Recover them?</source>
        <translation>PKM Studio неожиданно закрылся, когда в «%1» были несохранённые изменения (автосохранение %2). Восстановить их?</translation>
    </message>
    <message>
        <source>Recovered “%1”: save it to keep the changes.</source>
        <translation>Восстановлено «%1»: сохраните, чтобы не потерять изменения.</translation>
    </message>
    <message>
        <source>%1[*] — PKM Studio</source>
        <translation>%1[*] — PKM Studio</translation>
    </message>
    <message>
        <source>%1 no longer exists; removed from the recent files.</source>
        <translation>%1 больше не существует; файл удалён из списка недавних.</translation>
    </message>
    <message>
        <source>About PKM Studio</source>
        <translation>О программе PKM Studio</translation>
    </message>
    <message>
        <source>&lt;h3&gt;PKM Studio %1&lt;/h3&gt;&lt;p&gt;Design, analysis and teaching of parallel-kinematic mechanisms.&lt;/p&gt;&lt;p&gt;Licensed under the GNU General Public License, version 3 or later.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;PKM Studio %1&lt;/h3&gt;&lt;p&gt;Проектирование, анализ и преподавание механизмов параллельной кинематики.&lt;/p&gt;&lt;p&gt;Лицензия: GNU General Public License версии 3 или более поздней.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Export Drawing (DXF)</source>
        <translation>Экспорт чертежа (DXF)</translation>
    </message>
    <message>
        <source>DXF drawings (*.dxf);;All files (*)</source>
        <translation>Чертежи DXF (*.dxf);;Все файлы (*)</translation>
    </message>
    <message>
        <source>Cannot write the drawing to %1: %2.</source>
        <translation>Не удалось записать чертёж в %1: %2.</translation>
    </message>
    <message>
        <source>Wrote the drawing to %1 (DXF R12, mm).</source>
        <translation>Чертёж записан в %1 (DXF R12, мм).</translation>
    </message>
    <message>
        <source>Export Parameter Sheet</source>
        <translation>Экспорт листа параметров</translation>
    </message>
    <message>
        <source>PDF parameter sheets (*.pdf);;JSON (*.json);;CSV (*.csv)</source>
        <translation>Листы параметров PDF (*.pdf);;JSON (*.json);;CSV (*.csv)</translation>
    </message>
    <message>
        <source>Computing the parameter sheet…</source>
        <translation>Вычисляется лист параметров…</translation>
    </message>
    <message>
        <source>Wrote the parameter sheet to %1.</source>
        <translation>Лист параметров записан в %1.</translation>
    </message>
    <message>
        <source>Wrote the 2D view to %1.</source>
        <translation>2D-вид записан в %1.</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Язык</translation>
    </message>
    <message>
        <source>Main Toolbar</source>
        <translation>Основная панель инструментов</translation>
    </message>
    <message>
        <source>The language “%1” is not available.</source>
        <translation>Язык «%1» недоступен.</translation>
    </message>
    <message>
        <source>&amp;Source Documents…</source>
        <translation>&amp;Исходные документы…</translation>
    </message>
    <message>
        <source>Source Documents</source>
        <translation>Исходные документы</translation>
    </message>
    <message>
        <source>&lt;p&gt;PKM Studio models the mechanisms of these four documents: the active П-joint (1), MOMA (2), the O-X glide (3), the four-bar and the mobility formulas (4). Where a printed formula or number is wrong, the program uses the corrected one; the README&apos;s section on the mathematics lists each correction.&lt;/p&gt;%1</source>
        <translation>&lt;p&gt;PKM Studio моделирует механизмы этих четырёх документов: активный П-шарнир (1), MOMA (2), O-X glide (3), шарнирный четырёхзвенник и формулы подвижности (4). Где напечатанная формула или число неверны, программа использует исправленные; раздел README о математике перечисляет каждое исправление.&lt;/p&gt;%1</translation>
    </message>
    <message>
        <source>Play Toolbar</source>
        <translation>Панель воспроизведения</translation>
    </message>
    <message>
        <source>Play / &amp;Pause</source>
        <translation>Пуск / &amp;пауза</translation>
    </message>
    <message>
        <source>Move the chosen joint variable by itself, or stop it</source>
        <translation>Двигать выбранную обобщённую координату автоматически или остановить её</translation>
    </message>
    <message>
        <source>&amp;Bookmarks</source>
        <translation>&amp;Закладки</translation>
    </message>
    <message>
        <source>&amp;Add Bookmark</source>
        <translation>&amp;Добавить закладку</translation>
    </message>
    <message>
        <source>Keep this pose to come back to it (saved with the design)</source>
        <translation>Запомнить это положение, чтобы вернуться к нему (сохраняется вместе с конструкцией)</translation>
    </message>
    <message>
        <source>&amp;Previous Bookmark</source>
        <translation>&amp;Предыдущая закладка</translation>
    </message>
    <message>
        <source>&amp;Next Bookmark</source>
        <translation>&amp;Следующая закладка</translation>
    </message>
    <message>
        <source>&amp;Remove Current Bookmark</source>
        <translation>&amp;Удалить текущую закладку</translation>
    </message>
    <message>
        <source>Bookmark %1 kept: %2</source>
        <translation>Закладка %1 сохранена: %2</translation>
    </message>
    <message>
        <source>Bookmark %1 of %2: %3</source>
        <translation>Закладка %1 из %2: %3</translation>
    </message>
    <message>
        <source>No bookmarks yet: Bookmarks ▸ Add Bookmark (Ctrl+B) keeps the pose shown.</source>
        <translation>Закладок пока нет: Закладки ▸ Добавить закладку (Ctrl+B) запоминает показанное положение.</translation>
    </message>
    <message>
        <source>&amp;Presentation Mode</source>
        <translation>Режим &amp;презентации</translation>
    </message>
    <message>
        <source>Full screen, large text, high contrast: the linkage, its plot and the sliders (F5; Esc leaves)</source>
        <translation>Во весь экран, крупный текст, высокий контраст: механизм, его график и ползунки (F5; выход — Esc)</translation>
    </message>
    <message>
        <source>&amp;Text Size</source>
        <translation>Размер &amp;текста</translation>
    </message>
    <message>
        <source>Presentation mode: Esc or F5 leaves it; Page Up and Page Down step through the bookmarks.</source>
        <translation>Режим презентации: выход — Esc или F5; Page Up и Page Down листают закладки.</translation>
    </message>
    <message>
        <source>Equations</source>
        <translation>Уравнения</translation>
    </message>
    <message>
        <source>New from &amp;Template</source>
        <translation>Создать по &amp;шаблону</translation>
    </message>
    <message>
        <source>Export &amp;Animation (GIF, MP4, WebM)…</source>
        <translation>Экспорт &amp;анимации (GIF, MP4, WebM)…</translation>
    </message>
    <message>
        <source>5R (two driven cranks)</source>
        <translation>5R (два приводных кривошипа)</translation>
    </message>
    <message>
        <source>5R driven by two П-joints</source>
        <translation>5R с приводом от двух П-шарниров</translation>
    </message>
    <message>
        <source>Constant orientation, 2 DOF, with two П-joints</source>
        <translation>Постоянная ориентация, 2 степени свободы, с двумя П-шарнирами</translation>
    </message>
    <message>
        <source>3-RP̲R (three struts)</source>
        <translation>3-RP̲R (три телескопические штанги)</translation>
    </message>
    <message>
        <source>3-R̲RR (three driven cranks)</source>
        <translation>3-R̲RR (три приводных кривошипа)</translation>
    </message>
    <message>
        <source>3-P̲RR (three driven sliders)</source>
        <translation>3-P̲RR (три приводных ползуна)</translation>
    </message>
    <message>
        <source>2-P̲RR (two driven sliders, MOMA 3a)</source>
        <translation>2-P̲RR (два приводных ползуна, MOMA 3a)</translation>
    </message>
    <message>
        <source>&amp;User Guide</source>
        <translation>&amp;Руководство пользователя</translation>
    </message>
    <message>
        <source>What&apos;s &amp;This?</source>
        <translation>Что &amp;это?</translation>
    </message>
    <message>
        <source>The plots of this mechanism over the range of its input; the cursor marks the current pose. A right click saves a plot as a picture.</source>
        <translation>Графики этого механизма по диапазону его входа; курсор отмечает текущее положение. Щелчок правой кнопкой сохраняет график как изображение.</translation>
    </message>
    <message>
        <source>The workspace map: where the platform can go, coloured by the quantity chosen above it, with the singular curves. Click a point to move the platform there; the marker shows the current pose.</source>
        <translation>Карта рабочего пространства: куда может попасть платформа, в цвете выбранной над ней величины, с кривыми особых положений. Щелчок по точке переводит туда платформу; метка показывает текущее положение.</translation>
    </message>
    <message>
        <source>The linkage at its current pose. Drag a round handle to move a joint or the platform; the wheel zooms, the right button pans and F fits the mechanism. Faint ghosts are the other assembly modes: click one to switch to it. Limits and singular poses are told at the bottom.</source>
        <translation>Механизм в текущем положении. Перетащите круглую ручку, чтобы сдвинуть шарнир или платформу; колесо масштабирует, правая кнопка сдвигает вид, F вписывает механизм. Бледные силуэты — другие сборки: щелчок по одному переключает на неё. О пределах и особых положениях сообщается внизу.</translation>
    </message>
    <message>
        <source>The joint variables: each slider and its number set one variable of the mechanism, and the pose follows at once. A value the mechanism cannot reach is refused with a message.</source>
        <translation>Обобщённые координаты: каждый ползунок и его число задают одну координату механизма, и положение сразу следует за ними. Недостижимое значение отклоняется с сообщением.</translation>
    </message>
    <message>
        <source>Play moves the chosen joint variable by itself over the range set here, at this speed, in a loop, forth and back or once. It stops at a limit or before a singular pose and says why.</source>
        <translation>Воспроизведение само движет выбранную координату по заданному здесь диапазону с этой скоростью: по кругу, туда и обратно или один раз. Оно останавливается у предела или перед особым положением и объясняет почему.</translation>
    </message>
    <message>
        <source>The design: every dimension and mode of the mechanism. Change a value and the linkage, the values, the plots and the maps follow; every change can be undone (Ctrl+Z).</source>
        <translation>Конструкция: все размеры и режимы механизма. Измените значение — и схема, значения, графики и карты последуют за ним; любое изменение можно отменить (Ctrl+Z).</translation>
    </message>
    <message>
        <source>The values at this pose: joint variables, the Jacobian, its determinant and condition number and what the actuators deliver, each with its unit and meaning. At a singular pose a value that is infinite reads ∞ and one that is undefined reads —.</source>
        <translation>Значения в этом положении: координаты, якобиан, его определитель и число обусловленности и то, что дают приводы, — каждое с единицей и смыслом. В особом положении бесконечное значение показано как ∞, неопределённое — как —.</translation>
    </message>
    <message>
        <source>The mobility of the mechanism: its degrees of freedom counted by the structural formulas and by the rank of its loop equations at this pose, and where the formulas are wrong.</source>
        <translation>Подвижность механизма: число степеней свободы по структурным формулам и по рангу уравнений замкнутых контуров в этом положении, и где формулы ошибаются.</translation>
    </message>
    <message>
        <source>The governing equations of this mechanism with the source document&apos;s equation numbers, each followed by the same equation with the current numbers put in; they follow the pose.</source>
        <translation>Основные уравнения этого механизма с номерами уравнений исходного документа, за каждым — то же уравнение с подставленными текущими числами; они следуют за положением.</translation>
    </message>
    <message>
        <source>The mechanism in 3D at the current pose: drag to turn it, right-drag to pan, the wheel zooms and a double-click fits it. The sliders drive it as they drive the 2D view.</source>
        <translation>Механизм в 3D в текущем положении: перетаскивание поворачивает его, перетаскивание правой кнопкой сдвигает, колесо масштабирует, двойной щелчок вписывает. Ползунки управляют им так же, как видом 2D.</translation>
    </message>
    <message>
        <source>The assembly and working modes: the mode of the current pose, and a button for each other mode the mechanism can take here, which switches to it.</source>
        <translation>Сборки и рабочие режимы: режим текущего положения и кнопка для каждого другого режима, который механизм может принять здесь; она переключает на него.</translation>
    </message>
    <message>
        <source>Ellipses</source>
        <translation>Эллипсы</translation>
    </message>
    <message>
        <source>Velocity and force polygons and ellipses at the platform point (V)</source>
        <translation>Многоугольники и эллипсы скорости и силы в точке платформы (V)</translation>
    </message>
    <message>
        <source>&amp;Velocity and Force Shapes</source>
        <translation>Фигуры &amp;скорости и силы</translation>
    </message>
    <message>
        <source>The velocity and force polygons (solid) and ellipses (dashed) the actuators give at the platform point, to the scale of the legend (V)</source>
        <translation>Многоугольники (сплошные) и эллипсы (штриховые) скорости и силы, которые приводы дают в точке платформы, в масштабе легенды (V)</translation>
    </message>
    <message>
        <source>This design states no actuator limits, so there are no velocity and force shapes to draw.</source>
        <translation>В этой конструкции не заданы пределы приводов, поэтому фигур скорости и силы нет.</translation>
    </message>
    <message>
        <source>The velocity and force shapes cannot be scaled for this design: its home pose is singular.</source>
        <translation>Фигуры скорости и силы нельзя масштабировать для этой конструкции: её исходная поза особая.</translation>
    </message>
    <message>
        <source>Tolerances</source>
        <translation>Допуски</translation>
    </message>
    <message>
        <source>What the actuators must deliver at the platform; the workspace map shows where it holds</source>
        <translation>Что приводы должны обеспечить на платформе; карта рабочего пространства показывает, где это выполняется</translation>
    </message>
    <message>
        <source>The requirements are kept with the design; this mechanism has no workspace map to show where they hold.</source>
        <translation>Требования сохранены вместе с конструкцией; у этого механизма нет карты рабочего пространства, чтобы показать, где они выполняются.</translation>
    </message>
    <message>
        <source>Re&amp;quirements…</source>
        <translation>&amp;Требования…</translation>
    </message>
    <message>
        <source>Presentation P&amp;lot</source>
        <translation>Гра&amp;фик презентации</translation>
    </message>
    <message>
        <source>Values</source>
        <translation>Значения</translation>
    </message>
    <message>
        <source>The output of this mechanism is one angle: its speed, torque and stiffness are in “Values”; there is no platform point to draw shapes at.</source>
        <translation>Выход этого механизма — один угол: его скорость, момент и жёсткость — в «Значениях»; точки платформы, где рисовать фигуры, нет.</translation>
    </message>
</context>
<context>
    <name>pkm::MobilityPanel</name>
    <message>
        <source>✓ right</source>
        <translation>✓ верно</translation>
    </message>
    <message>
        <source>⚠ wrong</source>
        <translation>⚠ неверно</translation>
    </message>
    <message numerus="yes">
        <source>W = %1, but the rank gives M = %2: the formula counts %3 equations per loop, and %n of them are redundant.</source>
        <translation>
            <numerusform>W = %1, но по рангу M = %2: формула принимает число уравнений на контур равным %3, и %n из них избыточно.</numerusform>
            <numerusform>W = %1, но по рангу M = %2: формула принимает число уравнений на контур равным %3, и %n из них избыточны.</numerusform>
            <numerusform>W = %1, но по рангу M = %2: формула принимает число уравнений на контур равным %3, и %n из них избыточны.</numerusform>
        </translation>
    </message>
    <message>
        <source>A negative W rightly says “rigid”, but it is not the mobility: M = 0.</source>
        <translation>Отрицательное W верно указывает на жёсткую цепь, но подвижностью не является: M = 0.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Classroom example: the spatial parallelogram.&lt;/b&gt; The П-joint prototype&apos;s hinged parallelogram (a = 170 mm, b = 68 mm): four parallel revolute axes, counted as a spatial chain.</source>
        <translation>&lt;b&gt;Учебный пример: пространственный параллелограмм.&lt;/b&gt; Шарнирный параллелограмм прототипа П-шарнира (a = 170 мм, b = 68 мм): четыре параллельные оси вращательных пар, рассматриваемые как пространственная цепь.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Classroom example: the Bennett linkage.&lt;/b&gt; Four skew revolute axes, opposite links equal (a = 100 mm, b ≈ 188 mm) with twists α = 30°, β = 70° and a/sin α = b/sin β.</source>
        <translation>&lt;b&gt;Учебный пример: механизм Беннетта.&lt;/b&gt; Четыре скрещивающиеся оси вращательных пар, противоположные звенья равны (a = 100 мм, b ≈ 188 мм), углы скрещивания α = 30°, β = 70° и a/sin α = b/sin β.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Classroom example: a general spatial 4R loop.&lt;/b&gt; Four revolute axes in general position, without Bennett&apos;s proportions: the same counts as the Bennett linkage.</source>
        <translation>&lt;b&gt;Учебный пример: пространственный контур 4R общего вида.&lt;/b&gt; Четыре оси вращательных пар в общем положении, без пропорций Беннетта: подсчёт тот же, что и для механизма Беннетта.</translation>
    </message>
    <message>
        <source>the %1</source>
        <translation>%1</translation>
    </message>
    <message>
        <source>the ground (%1)</source>
        <translation>стойка (%1)</translation>
    </message>
    <message numerus="yes">
        <source>&lt;b&gt;Links&lt;/b&gt;: %1 and %n moving link(s), n = %n: %2.</source>
        <translation>
            <numerusform>&lt;b&gt;Звенья&lt;/b&gt;: %1 и %n подвижное звено, n = %n: %2.</numerusform>
            <numerusform>&lt;b&gt;Звенья&lt;/b&gt;: %1 и %n подвижных звена, n = %n: %2.</numerusform>
            <numerusform>&lt;b&gt;Звенья&lt;/b&gt;: %1 и %n подвижных звеньев, n = %n: %2.</numerusform>
        </translation>
    </message>
    <message>
        <source>&lt;b&gt;Pairs&lt;/b&gt;: %1.</source>
        <translation>&lt;b&gt;Пары&lt;/b&gt;: %1.</translation>
    </message>
    <message>
        <source>none</source>
        <translation>нет</translation>
    </message>
    <message>
        <source>Actuated: %1.</source>
        <translation>С приводом: %1.</translation>
    </message>
    <message numerus="yes">
        <source>&lt;b&gt;Loops&lt;/b&gt;: %n independent loop(s), L = %n.</source>
        <translation>
            <numerusform>&lt;b&gt;Контуры&lt;/b&gt;: %n независимый контур, L = %n.</numerusform>
            <numerusform>&lt;b&gt;Контуры&lt;/b&gt;: %n независимых контура, L = %n.</numerusform>
            <numerusform>&lt;b&gt;Контуры&lt;/b&gt;: %n независимых контуров, L = %n.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>&lt;b&gt;Idle freedoms&lt;/b&gt;: %n (a part spinning about its own axis), counted in every number below.</source>
        <translation>
            <numerusform>&lt;b&gt;Местные подвижности&lt;/b&gt;: %n (деталь, вращающаяся вокруг собственной оси); учтены во всех числах ниже.</numerusform>
            <numerusform>&lt;b&gt;Местные подвижности&lt;/b&gt;: %n (деталь, вращающаяся вокруг собственной оси); учтены во всех числах ниже.</numerusform>
            <numerusform>&lt;b&gt;Местные подвижности&lt;/b&gt;: %n (деталь, вращающаяся вокруг собственной оси); учтены во всех числах ниже.</numerusform>
        </translation>
    </message>
    <message>
        <source>At this pose the mechanism gains an instantaneous freedom (singularity).</source>
        <translation>В этом положении механизм получает мгновенную степень свободы (особое положение).</translation>
    </message>
    <message>
        <source>The rank of the loop equations drops from %1 to %2: the instantaneous mobility is %3, the mobility next to this pose %4.</source>
        <translation>Ранг уравнений замкнутости падает с %1 до %2: мгновенная подвижность равна %3, подвижность вблизи этого положения — %4.</translation>
    </message>
    <message>
        <source>With the actuators locked the mechanism can still move instantaneously here: it gains a freedom the actuators do not control (a direct singularity).</source>
        <translation>При застопоренных приводах механизм здесь всё ещё может мгновенно сдвинуться: он получает степень свободы, которой приводы не управляют (особое положение прямой кинематики).</translation>
    </message>
    <message>
        <source>⚠ Singular pose</source>
        <translation>⚠ Особое положение</translation>
    </message>
    <message>
        <source>Chebyshev (planar chains)</source>
        <translation>Чебышев (плоские цепи)</translation>
    </message>
    <message>
        <source>Does not apply: the chain has pairs that do not move in its plane.</source>
        <translation>Не применяется: в цепи есть пары, которые не движутся в её плоскости.</translation>
    </message>
    <message>
        <source>Does not apply: a spatial chain.</source>
        <translation>Не применяется: пространственная цепь.</translation>
    </message>
    <message>
        <source>Somov–Malyshev (spatial chains)</source>
        <translation>Сомов–Малышев (пространственные цепи)</translation>
    </message>
    <message>
        <source>The source document prints the last term as “+ P₁”: a typo. A pair of class 1 takes away one freedom, so − P₁.</source>
        <translation>В исходной статье последний член напечатан как «+ P₁» — это опечатка. Пара 1-го класса отнимает одну степень свободы, поэтому − P₁.</translation>
    </message>
    <message>
        <source>⚠ Here it matters: with + P₁ the formula would give W = %1.</source>
        <translation>⚠ Здесь это существенно: с + P₁ формула дала бы W = %1.</translation>
    </message>
    <message>
        <source>No loop equation is redundant: the structural count holds.</source>
        <translation>Ни одно уравнение замкнутости не избыточно: структурный подсчёт верен.</translation>
    </message>
    <message>
        <source>Bennett&apos;s proportions (opposite links equal, a/sin α = b/sin β) make them depend on the others, so the linkage moves although the count says it cannot.</source>
        <translation>пропорции Беннетта (противоположные звенья равны, a/sin α = b/sin β) делают их зависимыми от остальных, поэтому механизм движется, хотя подсчёт говорит, что не может.</translation>
    </message>
    <message>
        <source>the joint axes are parallel, so each loop moves in a plane and imposes only 3 of its 6 equations.</source>
        <translation>оси шарниров параллельны, поэтому каждый контур движется в плоскости и накладывает лишь 3 из своих 6 уравнений.</translation>
    </message>
    <message>
        <source>%1 independent equations already hold all %1 freedoms of the pairs: a rigid chain with constraints to spare.</source>
        <translation>независимых уравнений уже %1 — они удерживают все степени свободы пар (F = %1): жёсткая цепь с избыточными связями.</translation>
    </message>
    <message>
        <source>the pairs&apos; axes lie in a special way (parallel, or meeting in a point), so some equations repeat others: an overconstrained chain.</source>
        <translation>оси пар расположены особым образом (параллельны или пересекаются в одной точке), поэтому часть уравнений повторяет другие: цепь с избыточными связями.</translation>
    </message>
    <message numerus="yes">
        <source>%n redundant loop equation(s): %1</source>
        <translation>
            <numerusform>%n избыточное уравнение замкнутости: %1</numerusform>
            <numerusform>%n избыточных уравнения замкнутости: %1</numerusform>
            <numerusform>%n избыточных уравнений замкнутости: %1</numerusform>
        </translation>
    </message>
    <message>
        <source>From the rank of the constraint Jacobian</source>
        <translation>По рангу матрицы Якоби уравнений связей</translation>
    </message>
    <message numerus="yes">
        <source>An open chain, no loop: nothing holds the %n freedom(s) of its pairs, M = F = %n.</source>
        <translation>
            <numerusform>Открытая цепь, контуров нет: ничто не ограничивает %n степень свободы её пар, M = F = %n.</numerusform>
            <numerusform>Открытая цепь, контуров нет: ничто не ограничивает %n степени свободы её пар, M = F = %n.</numerusform>
            <numerusform>Открытая цепь, контуров нет: ничто не ограничивает %n степеней свободы её пар, M = F = %n.</numerusform>
        </translation>
    </message>
    <message>
        <source>F = %1 freedoms of the pairs; 6L = %2 loop equations.</source>
        <translation>F = %1 — число степеней свободы пар; 6L = %2 — число уравнений замкнутости.</translation>
    </message>
    <message>
        <source>At this pose: rank %1 of %2 → %3 (instantaneous).</source>
        <translation>В этом положении: ранг %1 из %2 → %3 (мгновенная).</translation>
    </message>
    <message>
        <source>Next to it: rank %1 of %2 → %3.</source>
        <translation>Вблизи него: ранг %1 из %2 → %3.</translation>
    </message>
    <message>
        <source>rank %1 of %2 loop equations → %3</source>
        <translation>ранг %1 из %2 уравнений замкнутости → %3</translation>
    </message>
    <message>
        <source>Mobility M = %1</source>
        <translation>Подвижность M = %1</translation>
    </message>
    <message>
        <source>(%1 at this pose)</source>
        <translation>(%1 в этом положении)</translation>
    </message>
    <message>
        <source>Actuation</source>
        <translation>Приводы</translation>
    </message>
    <message numerus="yes">
        <source>%n actuated freedom(s)</source>
        <translation>
            <numerusform>%n приводная степень свободы</numerusform>
            <numerusform>%n приводные степени свободы</numerusform>
            <numerusform>%n приводных степеней свободы</numerusform>
        </translation>
    </message>
    <message>
        <source>No pair is actuated.</source>
        <translation>Ни одна пара не имеет привода.</translation>
    </message>
    <message>
        <source>⚠ Under-actuated by %1:</source>
        <translation>⚠ Недостаёт приводов (%1):</translation>
    </message>
    <message numerus="yes">
        <source>%1 for mobility %2; with the actuators locked, it keeps %n freedom(s).</source>
        <translation>
            <numerusform>%1 при подвижности %2; при застопоренных приводах у него остаётся %n степень свободы.</numerusform>
            <numerusform>%1 при подвижности %2; при застопоренных приводах у него остаются %n степени свободы.</numerusform>
            <numerusform>%1 при подвижности %2; при застопоренных приводах у него остаётся %n степеней свободы.</numerusform>
        </translation>
    </message>
    <message>
        <source>Redundantly actuated: %1 for mobility %2.</source>
        <translation>Избыточное число приводов: %1 при подвижности %2.</translation>
    </message>
    <message>
        <source>✓ Fully actuated:</source>
        <translation>✓ Приводов достаточно:</translation>
    </message>
    <message>
        <source>%1 for mobility %2.</source>
        <translation>%1 при подвижности %2.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Verdict&lt;/b&gt;: %1</source>
        <translation>&lt;b&gt;Вывод&lt;/b&gt;: %1</translation>
    </message>
    <message>
        <source>Analyse:</source>
        <translation>Анализ:</translation>
    </message>
    <message>
        <source>This mechanism</source>
        <translation>Этот механизм</translation>
    </message>
    <message>
        <source>Example: spatial parallelogram</source>
        <translation>Пример: пространственный параллелограмм</translation>
    </message>
    <message>
        <source>Example: Bennett linkage</source>
        <translation>Пример: механизм Беннетта</translation>
    </message>
    <message>
        <source>Example: general spatial 4R (rigid)</source>
        <translation>Пример: пространственный 4R общего вида (жёсткий)</translation>
    </message>
    <message>
        <source>Classroom examples: chains where the structural formulas fail, and one where the counts predict the truth</source>
        <translation>Учебные примеры: цепи, для которых структурные формулы ошибаются, и одна, для которой подсчёт даёт верный ответ</translation>
    </message>
    <message>
        <source>No mechanism to analyse.</source>
        <translation>Нет механизма для анализа.</translation>
    </message>
    <message>
        <source>Analysing…</source>
        <translation>Анализ…</translation>
    </message>
    <message numerus="yes">
        <source>%n revolute</source>
        <translation>
            <numerusform>%n вращательная</numerusform>
            <numerusform>%n вращательные</numerusform>
            <numerusform>%n вращательных</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n prismatic</source>
        <translation>
            <numerusform>%n поступательная</numerusform>
            <numerusform>%n поступательные</numerusform>
            <numerusform>%n поступательных</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n screw</source>
        <translation>
            <numerusform>%n винтовая</numerusform>
            <numerusform>%n винтовые</numerusform>
            <numerusform>%n винтовых</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n cylindrical</source>
        <translation>
            <numerusform>%n цилиндрическая</numerusform>
            <numerusform>%n цилиндрические</numerusform>
            <numerusform>%n цилиндрических</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n planar cam</source>
        <translation>
            <numerusform>%n плоская кулачковая</numerusform>
            <numerusform>%n плоские кулачковые</numerusform>
            <numerusform>%n плоских кулачковых</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n spherical</source>
        <translation>
            <numerusform>%n сферическая</numerusform>
            <numerusform>%n сферические</numerusform>
            <numerusform>%n сферических</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>At this pose the mechanism gains %n instantaneous freedoms (singularity).</source>
        <translation>
            <numerusform>В этом положении механизм получает %n мгновенную степень свободы (особое положение).</numerusform>
            <numerusform>В этом положении механизм получает %n мгновенные степени свободы (особое положение).</numerusform>
            <numerusform>В этом положении механизм получает %n мгновенных степеней свободы (особое положение).</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>pkm::ModeBar</name>
    <message>
        <source>Modes: %1</source>
        <translation>Режимы: %1</translation>
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
        <translation>Переключиться: %1. Механизм остаётся в текущем режиме, пока вы не щёлкнете здесь или по его полупрозрачному силуэту на виде.</translation>
    </message>
    <message>
        <source>→ %1, %2:</source>
        <translation>→ %1, %2:</translation>
    </message>
    <message>
        <source>The mode the mechanism is in.</source>
        <translation>Режим, в котором находится механизм.</translation>
    </message>
</context>
<context>
    <name>pkm::OxGlidePanel</name>
    <message>
        <source>Form:</source>
        <translation>Форма:</translation>
    </message>
    <message>
        <source>O — extended</source>
        <translation>O — вытянутая</translation>
    </message>
    <message>
        <source>X — crossed</source>
        <translation>X — скрещенная</translation>
    </message>
    <message>
        <source>Work in the extended form: the rods splay outwards from the platform.</source>
        <translation>Работа в вытянутой форме: стержни расходятся от платформы наружу.</translation>
    </message>
    <message>
        <source>Work in the crossed form: the slider pairs pass each other and the rods cross.</source>
        <translation>Работа в скрещенной форме: пары ползунов проходят друг мимо друга, а стержни перекрещиваются.</translation>
    </message>
    <message>
        <source>Animate crossing</source>
        <translation>Анимировать переход</translation>
    </message>
    <message>
        <source>Raise the platform towards the O↔X crossing (y = l, x_CD − x_AB = s) and stop short of the singular pose there.</source>
        <translation>Поднять платформу к переходу O↔X (y = l, x_CD − x_AB = s) и остановиться, не доходя до особого положения.</translation>
    </message>
    <message>
        <source>Workspace O / X</source>
        <translation>Рабочее пространство O / X</translation>
    </message>
    <message>
        <source>Singularity map</source>
        <translation>Карта особых положений</translation>
    </message>
    <message>
        <source>The crossing stopped: the design changed.</source>
        <translation>Переход остановлен: конструкция изменилась.</translation>
    </message>
    <message>
        <source>Workspaces of the O and X forms (fig. 5)</source>
        <translation>Рабочие пространства форм O и X (рис. 5)</translation>
    </message>
    <message>
        <source>O↔X crossing y = l: singular</source>
        <translation>Переход O↔X y = l: особое положение</translation>
    </message>
    <message>
        <source>The crossing stopped: the pose was moved.</source>
        <translation>Переход остановлен: положение было изменено.</translation>
    </message>
    <message>
        <source>Crossing stopped.</source>
        <translation>Переход остановлен.</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Стоп</translation>
    </message>
    <message>
        <source>Raising the platform towards the O↔X crossing at y = l…</source>
        <translation>Платформа поднимается к переходу O↔X при y = l…</translation>
    </message>
    <message>
        <source>&lt;b&gt;Stopped %1 short of the singular pose.&lt;/b&gt; At y = l = %2 the slider pairs stand at x_CD − x_AB = s: the rods are perpendicular to the guides and parallel to each other, so the platform can swing sideways while the sliders hold still (a combined singularity), and it may leave in either form. Here the rods are at %3° to the guides. Passing needs the platform guided through that point: choose the form to leave in.</source>
        <translation>&lt;b&gt;Остановлено за %1 до особого положения.&lt;/b&gt; При y = l = %2 пары ползунов стоят в положении x_CD − x_AB = s: стержни перпендикулярны направляющим и параллельны друг другу, поэтому платформа может качаться в сторону при неподвижных ползунах (комбинированное особое положение) и выйти из него в любой форме. Здесь стержни расположены под углом %3° к направляющим. Для перехода платформу нужно провести через эту точку: выберите форму, в которой выйти.</translation>
    </message>
    <message>
        <source>The crossing stopped %1 below y = l, short of the singular pose x_CD − x_AB = s.</source>
        <translation>Переход остановлен на %1 ниже y = l, не доходя до особого положения x_CD − x_AB = s.</translation>
    </message>
    <message>
        <source>Leave in the extended (O) form</source>
        <translation>Выйти в вытянутой форме (O)</translation>
    </message>
    <message>
        <source>Leave in the crossed (X) form</source>
        <translation>Выйти в скрещенной форме (X)</translation>
    </message>
    <message>
        <source>Go back in the crossed (X) form</source>
        <translation>Вернуться в скрещенной форме (X)</translation>
    </message>
    <message>
        <source>Go back in the extended (O) form</source>
        <translation>Вернуться в вытянутой форме (O)</translation>
    </message>
    <message>
        <source>Switched to the crossed (X) form at the same platform position.</source>
        <translation>Выполнен переход в скрещенную форму (X) при том же положении платформы.</translation>
    </message>
    <message>
        <source>Switched to the extended (O) form at the same platform position.</source>
        <translation>Выполнен переход в вытянутую форму (O) при том же положении платформы.</translation>
    </message>
    <message>
        <source>The crossed (X) form is not available at this pose.</source>
        <translation>Скрещенная форма (X) недоступна в этом положении.</translation>
    </message>
    <message>
        <source>The extended (O) form is not available at this pose.</source>
        <translation>Вытянутая форма (O) недоступна в этом положении.</translation>
    </message>
    <message>
        <source>The platform is back at y = %1, in the crossed (X) form.</source>
        <translation>Платформа вернулась в y = %1, в скрещенной форме (X).</translation>
    </message>
    <message>
        <source>The platform is back at y = %1, in the extended (O) form.</source>
        <translation>Платформа вернулась в y = %1, в вытянутой форме (O).</translation>
    </message>
    <message>
        <source>Lowering the platform in the crossed (X) form…</source>
        <translation>Платформа опускается в скрещенной форме (X)…</translation>
    </message>
    <message>
        <source>Lowering the platform in the extended (O) form…</source>
        <translation>Платформа опускается в вытянутой форме (O)…</translation>
    </message>
</context>
<context>
    <name>pkm::PJointPlots</name>
    <message>
        <source>Geometry</source>
        <translation>Геометрия</translation>
    </message>
    <message>
        <source>Jacobian</source>
        <translation>Якобиан</translation>
    </message>
    <message>
        <source>Actuator</source>
        <translation>Привод</translation>
    </message>
    <message>
        <source>Fig. 8 — diagonal length d(θ), (2)</source>
        <translation>Рис. 8 — длина диагонали d(θ), (2)</translation>
    </message>
    <message>
        <source>Fig. 9 — passive angle φ(θ)</source>
        <translation>Рис. 9 — пассивный угол φ(θ)</translation>
    </message>
    <message>
        <source>Fig. 10 — transmission angle μ(θ)</source>
        <translation>Рис. 10 — угол передачи μ(θ)</translation>
    </message>
    <message>
        <source>Fig. 11 — Jacobian J(θ) = ∂d/∂θ, (7)</source>
        <translation>Рис. 11 — якобиан J(θ) = ∂d/∂θ, (7)</translation>
    </message>
    <message>
        <source>Fig. 12 — inverse Jacobian J⁻¹(θ), (8)</source>
        <translation>Рис. 12 — обратный якобиан J⁻¹(θ), (8)</translation>
    </message>
    <message>
        <source>Fig. 15 — output resolution Δθ = Δd/J</source>
        <translation>Рис. 15 — разрешение по выходу Δθ = Δd/J</translation>
    </message>
    <message>
        <source>Fig. 16 — output speed θ̇ = ḋ_max/J</source>
        <translation>Рис. 16 — скорость выходного звена θ̇ = ḋ_max/J</translation>
    </message>
    <message>
        <source>Fig. 17 — output torque T = J·F_max, (13)</source>
        <translation>Рис. 17 — выходной момент T = J·F_max, (13)</translation>
    </message>
    <message>
        <source>a = %1 mm, k = %2, θ %3°…%4°; family at the same a</source>
        <translation>a = %1 мм, k = %2, θ %3°…%4°; семейство при том же a</translation>
    </message>
    <message>
        <source>diagonal OA from the base OB</source>
        <translation>диагональ OA относительно основания OB</translation>
    </message>
    <message>
        <source>at A, diagonal to crank; J = a·sin μ</source>
        <translation>в точке A, между диагональю и кривошипом; J = a·sin μ</translation>
    </message>
    <message>
        <source>ḋ = J·θ̇; a = %1 mm, k = %2</source>
        <translation>ḋ = J·θ̇; a = %1 мм, k = %2</translation>
    </message>
    <message>
        <source>θ̇ = J⁻¹·ḋ; J⁻¹ → ∞ at θ = ±90°</source>
        <translation>θ̇ = J⁻¹·ḋ; J⁻¹ → ∞ при θ = ±90°</translation>
    </message>
    <message>
        <source>one motor step Δd = %1 mm</source>
        <translation>один шаг двигателя Δd = %1 мм</translation>
    </message>
    <message>
        <source>at the maximum linear speed ḋ_max = %1 mm/s</source>
        <translation>при максимальной линейной скорости ḋ_max = %1 мм/с</translation>
    </message>
    <message>
        <source>F_max = %1 N; motor torque T_M = %2 N·m at any θ (15)</source>
        <translation>F_max = %1 Н; момент двигателя T_M = %2 Н·м при любом θ (15)</translation>
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
        <translation>эта конструкция (k = %1)</translation>
    </message>
    <message>
        <source>beyond its θ range</source>
        <translation>вне её диапазона θ</translation>
    </message>
    <message>
        <source>k = %1</source>
        <translation>k = %1</translation>
    </message>
    <message>
        <source>recommended %1°…%2° (J ≥ %3 % of best)</source>
        <translation>рекомендуемый %1°…%2° (J ≥ %3 % от наилучшего)</translation>
    </message>
    <message>
        <source>steep region</source>
        <translation>крутой участок</translation>
    </message>
    <message>
        <source>μ &lt; %1°: force almost along the crank</source>
        <translation>μ &lt; %1°: сила направлена почти вдоль кривошипа</translation>
    </message>
</context>
<context>
    <name>pkm::PictureDialog</name>
    <message>
        <source>PNG pictures (*.png)</source>
        <translation>Изображения PNG (*.png)</translation>
    </message>
    <message>
        <source>SVG drawings (*.svg)</source>
        <translation>Рисунки SVG (*.svg)</translation>
    </message>
    <message>
        <source>PDF documents (*.pdf)</source>
        <translation>Документы PDF (*.pdf)</translation>
    </message>
    <message>
        <source>%1 × %2 pixels is not a picture size: each side must be from %3 to %4.</source>
        <translation>%1 × %2 пикс. — недопустимый размер изображения: каждая сторона должна быть от %3 до %4.</translation>
    </message>
    <message>
        <source>%1 dpi is not a resolution: it must be from %2 to %3 dpi.</source>
        <translation>%1 dpi — недопустимое разрешение: оно должно быть от %2 до %3 dpi.</translation>
    </message>
    <message>
        <source>The %1 picture could not be drawn.</source>
        <translation>Не удалось нарисовать изображение %1.</translation>
    </message>
    <message>
        <source>There is not enough memory for a picture of %1 × %2 pixels.</source>
        <translation>Недостаточно памяти для изображения %1 × %2 пикс.</translation>
    </message>
    <message>
        <source>Drawn by %1</source>
        <translation>Нарисовано в %1</translation>
    </message>
    <message>
        <source>“%1” is not a picture format: the file name must end in .png, .svg or .pdf.</source>
        <translation>«%1» — не формат изображения: имя файла должно оканчиваться на .png, .svg или .pdf.</translation>
    </message>
    <message>
        <source>There is no plot to draw.</source>
        <translation>Нет графика для рисования.</translation>
    </message>
    <message>
        <source>“%1” could not be opened for writing: %2.</source>
        <translation>Не удалось открыть «%1» для записи: %2.</translation>
    </message>
    <message>
        <source>The picture could not be written to “%1”: %2.</source>
        <translation>Не удалось записать изображение в «%1»: %2.</translation>
    </message>
    <message>
        <source>“%1” could not be saved: %2.</source>
        <translation>Не удалось сохранить «%1»: %2.</translation>
    </message>
    <message>
        <source>Save picture…</source>
        <translation>Сохранить изображение…</translation>
    </message>
    <message>
        <source>Save this plot as a PNG picture, an SVG or a PDF drawing</source>
        <translation>Сохранить этот график как изображение PNG или как рисунок SVG или PDF</translation>
    </message>
    <message>
        <source>Save Picture</source>
        <translation>Сохранение изображения</translation>
    </message>
    <message>
        <source>Picture Size</source>
        <translation>Размер изображения</translation>
    </message>
    <message>
        <source>%1 × %2</source>
        <translation>%1 × %2</translation>
    </message>
    <message>
        <source>As shown — %1</source>
        <translation>Как на экране — %1</translation>
    </message>
    <message>
        <source>Twice as shown — %1</source>
        <translation>Вдвое больше — %1</translation>
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
        <translation>Произвольный</translation>
    </message>
    <message>
        <source> px</source>
        <translation> пикс.</translation>
    </message>
    <message>
        <source>%1 dpi</source>
        <translation>%1 dpi</translation>
    </message>
    <message>
        <source>An SVG drawing is scalable: its size is in CSS pixels.</source>
        <translation>Рисунок SVG масштабируется: его размер задаётся в пикселях CSS.</translation>
    </message>
    <message>
        <source>The PDF&apos;s page is the size in pixels at this resolution.</source>
        <translation>Размер страницы PDF — размер в пикселях при этом разрешении.</translation>
    </message>
    <message>
        <source>Stored in the PNG: the size it prints at.</source>
        <translation>Записывается в PNG и задаёт размер при печати.</translation>
    </message>
    <message>
        <source>&amp;Size:</source>
        <translation>&amp;Размер:</translation>
    </message>
    <message>
        <source>&amp;Width:</source>
        <translation>&amp;Ширина:</translation>
    </message>
    <message>
        <source>&amp;Height:</source>
        <translation>&amp;Высота:</translation>
    </message>
    <message>
        <source>&amp;Resolution:</source>
        <translation>Ра&amp;зрешение:</translation>
    </message>
    <message>
        <source>%1 × %2 mm</source>
        <translation>%1 × %2 мм</translation>
    </message>
    <message>
        <source>%1 × %2 pixels</source>
        <translation>%1 × %2 пикс.</translation>
    </message>
    <message>
        <source>An SVG drawing of %1 (CSS pixels), lines and text as vectors.</source>
        <translation>Рисунок SVG размером %1 (пиксели CSS), линии и текст — векторные.</translation>
    </message>
    <message>
        <source>A PDF page of %1: %2 at %3 dpi, lines and text as vectors.</source>
        <translation>Страница PDF размером %1: %2 при %3 dpi, линии и текст — векторные.</translation>
    </message>
    <message>
        <source>A PNG picture of %1; it prints at %2 at %3 dpi.</source>
        <translation>Изображение PNG размером %1; при печати — %2 при %3 dpi.</translation>
    </message>
</context>
<context>
    <name>pkm::PlanarParallelPanel</name>
    <message>
        <source>Add leg 3</source>
        <translation>Добавить ногу 3</translation>
    </message>
    <message>
        <source>Remove leg 3</source>
        <translation>Удалить ногу 3</translation>
    </message>
    <message>
        <source>Change the platform</source>
        <translation>Изменить платформу</translation>
    </message>
    <message>
        <source>Change the type of leg %1</source>
        <translation>Изменить тип ноги %1</translation>
    </message>
    <message>
        <source>Change the working mode of leg %1</source>
        <translation>Изменить рабочий режим ноги %1</translation>
    </message>
    <message>
        <source>Legs</source>
        <translation>Ноги</translation>
    </message>
    <message>
        <source>&amp;Platform:</source>
        <translation>&amp;Платформа:</translation>
    </message>
    <message>
        <source>Add leg</source>
        <translation>Добавить ногу</translation>
    </message>
    <message>
        <source>A third leg, a strut opposite the other two: the platform becomes a free body (3 DOF).</source>
        <translation>Третья нога, штанга напротив двух других: платформа становится свободным телом (3 степени свободы).</translation>
    </message>
    <message>
        <source>Two legs: the platform becomes a point, or keeps a constant orientation if both legs are P̲RR or П̲RR.</source>
        <translation>Две ноги: платформа становится точкой или сохраняет постоянную ориентацию, если обе ноги P̲RR или П̲RR.</translation>
    </message>
    <message>
        <source>a point (2 legs, x and y)</source>
        <translation>точка (2 ноги, x и y)</translation>
    </message>
    <message>
        <source>constant orientation (2 legs, x and y)</source>
        <translation>постоянная ориентация (2 ноги, x и y)</translation>
    </message>
    <message>
        <source>free body (3 legs, x, y and φ)</source>
        <translation>свободное тело (3 ноги, x, y и φ)</translation>
    </message>
    <message>
        <source>Leg %1:</source>
        <translation>Нога %1:</translation>
    </message>
    <message>
        <source>R̲RR: driven crank and link</source>
        <translation>R̲RR: приводной кривошип и шатун</translation>
    </message>
    <message>
        <source>P̲RR: driven slider and link</source>
        <translation>P̲RR: приводной ползун и шатун</translation>
    </message>
    <message>
        <source>RP̲R: telescopic strut</source>
        <translation>RP̲R: телескопическая штанга</translation>
    </message>
    <message>
        <source>П̲RR: active П-joint and link</source>
        <translation>П̲RR: активный П-шарнир и шатун</translation>
    </message>
    <message>
        <source>The leg&apos;s joints from the base, the actuated one underlined.</source>
        <translation>Шарниры ноги от основания, приводной подчёркнут.</translation>
    </message>
    <message>
        <source>working mode +1</source>
        <translation>рабочий режим +1</translation>
    </message>
    <message>
        <source>working mode −1</source>
        <translation>рабочий режим −1</translation>
    </message>
    <message>
        <source>+1: the elbow left of the line from A to the platform point (P̲RR: the slider beyond the foot of the perpendicular).</source>
        <translation>+1: локоть слева от линии от A к точке платформы (P̲RR: ползун за основанием перпендикуляра).</translation>
    </message>
    <message>
        <source>point</source>
        <translation>точка</translation>
    </message>
    <message>
        <source>constant orientation</source>
        <translation>постоянная ориентация</translation>
    </message>
    <message>
        <source>free body</source>
        <translation>свободное тело</translation>
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
        <translation>Пуск</translation>
    </message>
    <message>
        <source>/s</source>
        <translation>/с</translation>
    </message>
    <message>
        <source>Play: move the chosen joint variable by itself (stops at a limit or before a singular pose)</source>
        <translation>Пуск: выбранная обобщённая координата движется сама (останавливается на пределе или перед особым положением)</translation>
    </message>
    <message>
        <source>from</source>
        <translation>от</translation>
    </message>
    <message>
        <source>to</source>
        <translation>до</translation>
    </message>
    <message>
        <source>speed</source>
        <translation>скорость</translation>
    </message>
    <message>
        <source>Loop</source>
        <translation>По кругу</translation>
    </message>
    <message>
        <source>Forth and back</source>
        <translation>Туда и обратно</translation>
    </message>
    <message>
        <source>Once</source>
        <translation>Один раз</translation>
    </message>
    <message>
        <source>At the end of the range: start again, turn back, or stop</source>
        <translation>В конце диапазона: начать сначала, повернуть обратно или остановиться</translation>
    </message>
</context>
<context>
    <name>pkm::Player</name>
    <message>
        <source>inverse</source>
        <translation>обратной кинематики</translation>
    </message>
    <message>
        <source>direct</source>
        <translation>прямой кинематики</translation>
    </message>
    <message>
        <source>combined</source>
        <translation>комбинированное</translation>
    </message>
    <message>
        <source>Play needs a range: “from” must be below “to” for %1, and the speed above 0.</source>
        <translation>Для воспроизведения нужен диапазон: для %1 значение «от» должно быть меньше «до», а скорость — больше 0.</translation>
    </message>
    <message>
        <source>Play stopped before a singular pose (%1) at %2 = %3.</source>
        <translation>Воспроизведение остановлено перед особым положением (%1) при %2 = %3.</translation>
    </message>
    <message>
        <source>Play reached the end of its range.</source>
        <translation>Воспроизведение дошло до конца диапазона.</translation>
    </message>
    <message>
        <source>Play turned back: %1</source>
        <translation>Воспроизведение повернуло обратно: %1</translation>
    </message>
    <message>
        <source>Play stopped close to a singular pose at %1 = %2.</source>
        <translation>Воспроизведение остановлено вблизи особого положения при %1 = %2.</translation>
    </message>
    <message>
        <source>Play turned back close to a singular pose at %1 = %2.</source>
        <translation>Воспроизведение повернуло обратно вблизи особого положения при %1 = %2.</translation>
    </message>
    <message>
        <source>Play turned back before a singular pose (%1) at %2 = %3.</source>
        <translation>Воспроизведение повернуло обратно перед особым положением (%1) при %2 = %3.</translation>
    </message>
</context>
<context>
    <name>pkm::Renderer3D</name>
    <message>
        <source>No OpenGL context is current.</source>
        <translation>Нет текущего контекста OpenGL.</translation>
    </message>
    <message>
        <source>The driver offers OpenGL %1%2.%3; the 3D view needs OpenGL 3.3.</source>
        <translation>Драйвер предоставляет OpenGL %1%2.%3, а для 3D-вида нужен OpenGL 3.3.</translation>
    </message>
    <message>
        <source>The OpenGL 3.3 core functions could not be resolved.</source>
        <translation>Не удалось получить функции ядра OpenGL 3.3.</translation>
    </message>
    <message>
        <source>OpenGL %1.%2 (%3), %4</source>
        <translation>OpenGL %1.%2 (%3), %4</translation>
    </message>
    <message>
        <source>The 3D view&apos;s shaders could not be built: %1</source>
        <translation>Не удалось собрать шейдеры 3D-вида: %1</translation>
    </message>
    <message>
        <source>A picture of %1 × %2 pixels is not possible: the largest is %3 × %3.</source>
        <translation>Изображение %1 × %2 пикселей невозможно: наибольший размер — %3 × %3.</translation>
    </message>
    <message>
        <source>The OpenGL driver could not make a framebuffer of %1 × %2 pixels.</source>
        <translation>Драйвер OpenGL не смог создать кадровый буфер %1 × %2 пикселей.</translation>
    </message>
    <message>
        <source>No OpenGL context could be created on the “%1” display platform.</source>
        <translation>Не удалось создать контекст OpenGL на платформе отображения «%1».</translation>
    </message>
    <message>
        <source>The driver offers OpenGL %1%2.%3 only.</source>
        <translation>Драйвер предоставляет только OpenGL %1%2.%3.</translation>
    </message>
    <message>
        <source>The OpenGL context could not be made current on an offscreen surface.</source>
        <translation>Не удалось сделать контекст OpenGL текущим на внеэкранной поверхности.</translation>
    </message>
</context>
<context>
    <name>pkm::RequirementsDialog</name>
    <message>
        <source>Requirements</source>
        <translation>Требования</translation>
    </message>
    <message>
        <source>What the actuators must deliver at the platform. The workspace map “where the requirements hold” shows, in green, where every checked one does, from the actuators&apos; limits in the design.</source>
        <translation>Что приводы должны обеспечить на платформе. Карта рабочего пространства «где требования выполняются» показывает зелёным, где выполняется каждое отмеченное, по пределам приводов в конструкции.</translation>
    </message>
    <message>
        <source>This design states no actuator limits: there is nothing to require.</source>
        <translation>В этой конструкции не заданы пределы приводов: требовать нечего.</translation>
    </message>
    <message>
        <source>Also required (from the file, kept as it is): %1</source>
        <translation>Также требуется (из файла, сохранено как есть): %1</translation>
    </message>
</context>
<context>
    <name>pkm::SetParameterCommand</name>
    <message>
        <source>Change %1</source>
        <translation>Изменить %1</translation>
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
        <translation>%1 (по оси абсцисс: %2)</translation>
    </message>
</context>
<context>
    <name>pkm::TolerancePanel</name>
    <message>
        <source>Give a tolerance to at least one parameter.</source>
        <translation>Задайте допуск хотя бы одному параметру.</translation>
    </message>
    <message>
        <source>First-order worst case at this pose: |Δx| ≤ %1 (%2).</source>
        <translation>Наихудший случай в первом приближении в этом положении: |Δx| ≤ %1 (%2).</translation>
    </message>
    <message>
        <source>Monte Carlo</source>
        <translation>Монте-Карло</translation>
    </message>
    <message>
        <source>Solving %1 designs within the tolerances…</source>
        <translation>Решение %1 конструкций в пределах допусков…</translation>
    </message>
    <message>
        <source>Monte Carlo cancelled.</source>
        <translation>Монте-Карло отменено.</translation>
    </message>
    <message>
        <source>%1 of %2 samples did not assemble (%3 %).</source>
        <translation>%1 из %2 выборок не собрались (%3 %).</translation>
    </message>
    <message>
        <source>No sample assembled: the distribution is undefined.</source>
        <translation>Ни одна выборка не собралась: распределение не определено.</translation>
    </message>
    <message>
        <source>Monte Carlo |Δx|: mean %1, σ %2, max %3. %4</source>
        <translation>Монте-Карло |Δx|: среднее %1, σ %2, макс. %3. %4</translation>
    </message>
    <message>
        <source>|Δx| (%1)</source>
        <translation>|Δx| (%1)</translation>
    </message>
    <message>
        <source>samples</source>
        <translation>выборки</translation>
    </message>
    <message>
        <source>This mechanism has no planar workspace to map.</source>
        <translation>У этого механизма нет плоского рабочего пространства для карты.</translation>
    </message>
    <message>
        <source>Worst-case map</source>
        <translation>Карта наихудшего случая</translation>
    </message>
    <message>
        <source>Mapping the worst-case error over the workspace…</source>
        <translation>Построение карты наихудшей погрешности по рабочему пространству…</translation>
    </message>
    <message>
        <source>Map cancelled.</source>
        <translation>Карта отменена.</translation>
    </message>
    <message>
        <source>Worst case over the workspace: %1 to %2 (%3 cells; dark: small, bright: large).</source>
        <translation>Наихудший случай по рабочему пространству: от %1 до %2 (%3 ячеек; тёмные — малая, светлые — большая).</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Параметр</translation>
    </message>
    <message>
        <source>Tolerance</source>
        <translation>Допуск</translation>
    </message>
    <message>
        <source>Error part</source>
        <translation>Вклад</translation>
    </message>
    <message>
        <source>Share</source>
        <translation>Доля</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>Параметры</translation>
    </message>
    <message>
        <source>Monte Carlo and map</source>
        <translation>Монте-Карло и карта</translation>
    </message>
    <message>
        <source>Samples:</source>
        <translation>Выборок:</translation>
    </message>
    <message>
        <source>Normal (tol = 3σ)</source>
        <translation>Нормальное (допуск = 3σ)</translation>
    </message>
    <message>
        <source>Draw normal samples with the tolerance as 3σ instead of uniform ones within ±tol</source>
        <translation>Брать нормальные выборки с допуском 3σ вместо равномерных в пределах ±допуска</translation>
    </message>
    <message>
        <source>Solve many designs drawn within the tolerances at this pose (fixed seed)</source>
        <translation>Решить много конструкций, взятых в пределах допусков, в этом положении (фиксированное начальное число)</translation>
    </message>
    <message>
        <source>Map</source>
        <translation>Карта</translation>
    </message>
    <message>
        <source>The first-order worst case over the workspace</source>
        <translation>Наихудший случай в первом приближении по рабочему пространству</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Очистить</translation>
    </message>
    <message>
        <source>Remove every tolerance (undoable)</source>
        <translation>Удалить все допуски (можно отменить)</translation>
    </message>
</context>
<context>
    <name>pkm::ValuesTable</name>
    <message>
        <source>Pose</source>
        <translation>Положение</translation>
    </message>
    <message>
        <source>Jacobian</source>
        <translation>Якобиан</translation>
    </message>
    <message>
        <source>Derived</source>
        <translation>Производные величины</translation>
    </message>
    <message>
        <source>none</source>
        <translation>нет</translation>
    </message>
    <message>
        <source>inverse</source>
        <translation>обратное</translation>
    </message>
    <message>
        <source>direct</source>
        <translation>прямое</translation>
    </message>
    <message>
        <source>combined</source>
        <translation>комбинированное</translation>
    </message>
    <message>
        <source>Quantity</source>
        <translation>Величина</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Значение</translation>
    </message>
    <message>
        <source>Meaning</source>
        <translation>Описание</translation>
    </message>
    <message>
        <source>Singularity</source>
        <translation>Особое положение</translation>
    </message>
    <message>
        <source>class</source>
        <translation>класс</translation>
    </message>
    <message>
        <source>none, inverse, direct or combined</source>
        <translation>нет, обратное, прямое или комбинированное</translation>
    </message>
    <message>
        <source>%1 (margin %2)</source>
        <translation>%1 (запас %2)</translation>
    </message>
    <message>
        <source>Capability</source>
        <translation>Возможности приводов</translation>
    </message>
    <message>
        <source>Capability: as at a singular pose</source>
        <translation>Возможности: как в особом положении</translation>
    </message>
    <message>
        <source>near inverse</source>
        <translation>вблизи обратного</translation>
    </message>
    <message>
        <source>near direct</source>
        <translation>вблизи прямого</translation>
    </message>
    <message>
        <source>near combined</source>
        <translation>вблизи комбинированного</translation>
    </message>
    <message>
        <source>Point at a row to read its meaning in full.</source>
        <translation>Наведите указатель на строку, чтобы прочитать её описание полностью.</translation>
    </message>
</context>
<context>
    <name>pkm::VariablePanel</name>
    <message>
        <source>input, actuated</source>
        <translation>вход, с приводом</translation>
    </message>
    <message>
        <source>input</source>
        <translation>вход</translation>
    </message>
    <message>
        <source>output</source>
        <translation>выход</translation>
    </message>
    <message>
        <source>Drag to set %1 (%2), from %3 to %4</source>
        <translation>Перетащите, чтобы задать %1 (%2), от %3 до %4</translation>
    </message>
</context>
<context>
    <name>pkm::VideoWriter</name>
    <message>
        <source>A video is %1 to %2 pixels wide and %1 to %3 high, in even numbers (e.g. 1280x720 or 1920x1080), not %4x%5.</source>
        <translation>Ширина видео — от %1 до %2 пикселей, высота — от %1 до %3, чётными числами (например, 1280x720 или 1920x1080), а не %4x%5.</translation>
    </message>
    <message>
        <source>Cannot write &apos;%1&apos;: %2.</source>
        <translation>Не удаётся записать «%1»: %2.</translation>
    </message>
    <message>
        <source>unknown error</source>
        <translation>неизвестная ошибка</translation>
    </message>
    <message>
        <source>This build of FFmpeg&apos;s libavformat cannot write %1 files.</source>
        <translation>Эта сборка libavformat (FFmpeg) не умеет записывать файлы %1.</translation>
    </message>
    <message>
        <source>FFmpeg is out of memory.</source>
        <translation>FFmpeg не хватает памяти.</translation>
    </message>
    <message>
        <source>FFmpeg could not start the %1 encoder (%2): %3.</source>
        <translation>FFmpeg не удалось запустить кодировщик %1 (%2): %3.</translation>
    </message>
    <message>
        <source>FFmpeg&apos;s libavcodec here has no H.264 encoder: MP4 needs libx264 (Debian&apos;s libavcodec has it).</source>
        <translation>В libavcodec (FFmpeg) здесь нет кодировщика H.264: для MP4 нужен libx264 (в libavcodec из Debian он есть).</translation>
    </message>
    <message>
        <source>FFmpeg&apos;s libavcodec here has no VP9 or VP8 encoder: WebM needs libvpx (Debian&apos;s libavcodec has it).</source>
        <translation>В libavcodec (FFmpeg) здесь нет кодировщика VP9 или VP8: для WebM нужен libvpx (в libavcodec из Debian он есть).</translation>
    </message>
    <message>
        <source>FFmpeg&apos;s libswscale cannot convert the frames to YUV 4:2:0.</source>
        <translation>libswscale (FFmpeg) не может преобразовать кадры в YUV 4:2:0.</translation>
    </message>
    <message>
        <source>The video is not open.</source>
        <translation>Видео не открыто.</translation>
    </message>
    <message>
        <source>A video needs at least one frame.</source>
        <translation>Видео должно содержать хотя бы один кадр.</translation>
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
        <translation>Имена шарниров (A, B, … как на 2D-виде) поверх модели</translation>
    </message>
    <message>
        <source>Fit</source>
        <translation>Вписать</translation>
    </message>
    <message>
        <source>Show the whole mechanism (F, or double-click)</source>
        <translation>Показать весь механизм (F или двойной щелчок)</translation>
    </message>
    <message>
        <source>Front</source>
        <translation>Спереди</translation>
    </message>
    <message>
        <source>Look at the mechanism plane, as the 2D view does (1)</source>
        <translation>Смотреть на плоскость механизма, как в 2D-виде (1)</translation>
    </message>
    <message>
        <source>Top</source>
        <translation>Сверху</translation>
    </message>
    <message>
        <source>Look down from above (7)</source>
        <translation>Смотреть сверху вниз (7)</translation>
    </message>
    <message>
        <source>Side</source>
        <translation>Сбоку</translation>
    </message>
    <message>
        <source>Look from the right (3)</source>
        <translation>Смотреть справа (3)</translation>
    </message>
    <message>
        <source>Isometric</source>
        <translation>Изометрия</translation>
    </message>
    <message>
        <source>Look from the front, right and above at once</source>
        <translation>Смотреть одновременно спереди, справа и сверху</translation>
    </message>
    <message>
        <source>Perspective</source>
        <translation>Перспектива</translation>
    </message>
    <message>
        <source>Perspective when on, orthographic (true to scale) when off (5)</source>
        <translation>Включено — перспектива, выключено — ортогональная проекция (в масштабе) (5)</translation>
    </message>
    <message>
        <source>Save picture…</source>
        <translation>Сохранить изображение…</translation>
    </message>
    <message>
        <source>Save the 3D view as a PNG picture at twice its size</source>
        <translation>Сохранить 3D-вид как изображение PNG вдвое большего размера</translation>
    </message>
    <message>
        <source>%1 × %2 pixels is not a picture size: each side must be from 16 to 8000.</source>
        <translation>%1 × %2 пикселей — недопустимый размер изображения: каждая сторона должна быть от 16 до 8000.</translation>
    </message>
    <message>
        <source>The picture could not be rendered. %1</source>
        <translation>Не удалось построить изображение. %1</translation>
    </message>
    <message>
        <source>“%1” could not be opened for writing: %2</source>
        <translation>Не удалось открыть «%1» для записи: %2</translation>
    </message>
    <message>
        <source>The picture could not be written to “%1”.</source>
        <translation>Не удалось записать изображение в «%1».</translation>
    </message>
    <message>
        <source>“%1” could not be saved: %2</source>
        <translation>Не удалось сохранить «%1»: %2</translation>
    </message>
    <message>
        <source>Save picture</source>
        <translation>Сохранить изображение</translation>
    </message>
    <message>
        <source>PNG pictures (*.png)</source>
        <translation>Изображения PNG (*.png)</translation>
    </message>
    <message>
        <source>%1 × %2 pixels</source>
        <translation>%1 × %2 пикс.</translation>
    </message>
    <message>
        <source>%1 (twice the view)</source>
        <translation>%1 (вдвое больше вида)</translation>
    </message>
    <message>
        <source>Picture size:</source>
        <translation>Размер изображения:</translation>
    </message>
</context>
<context>
    <name>pkm::ViewPicture</name>
    <message>
        <source>Save 2D View Picture</source>
        <translation>Сохранить изображение 2D-вида</translation>
    </message>
</context>
<context>
    <name>pkm::WorkspaceMapView</name>
    <message>
        <source>No mechanism.</source>
        <translation>Механизм не задан.</translation>
    </message>
    <message>
        <source>No planar workspace: the outputs of this mechanism are not a point of the plane, so there is no workspace map to show.</source>
        <translation>Нет плоского рабочего пространства: выходные координаты этого механизма — не точка плоскости, поэтому карту рабочего пространства построить нельзя.</translation>
    </message>
    <message>
        <source>Workspace map</source>
        <translation>Карта рабочего пространства</translation>
    </message>
    <message>
        <source>Workspace empty in the design&apos;s working and assembly modes</source>
        <translation>Рабочее пространство пусто при рабочем режиме и варианте сборки конструкции</translation>
    </message>
    <message>
        <source>κ(J), log scale (colours end at %1)</source>
        <translation>κ(J), логарифмическая шкала (цвета до %1)</translation>
    </message>
    <message>
        <source>det J (colours clipped at ±%1)</source>
        <translation>det J (цвета ограничены на ±%1)</translation>
    </message>
    <message>
        <source>The colours end at the 98th percentile of κ(J) over the workspace, %1; κ → ∞ at the singularities.</source>
        <translation>Цветовая шкала заканчивается на 98-м процентиле κ(J) по рабочему пространству, %1; в особых положениях κ → ∞.</translation>
    </message>
    <message>
        <source>The colours are clipped at ±%1, the larger of the 5th and 95th percentiles of |det J| over the workspace: det J → ±∞ at inverse singularities, 0 at direct ones.</source>
        <translation>Цвета ограничены на ±%1 — большем из 5-го и 95-го процентилей |det J| по рабочему пространству: в особых положениях обратной кинематики det J → ±∞, в особых положениях прямой кинематики det J = 0.</translation>
    </message>
    <message>
        <source>workspace boundary</source>
        <translation>граница рабочего пространства</translation>
    </message>
    <message>
        <source>: none</source>
        <translation>: нет</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>inverse singularity</source>
        <translation>особое положение обратной кинематики</translation>
    </message>
    <message>
        <source>direct singularity</source>
        <translation>особое положение прямой кинематики</translation>
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
        <translation>&amp;Карта:</translation>
    </message>
    <message>
        <source>condition number κ(J)</source>
        <translation>число обусловленности κ(J)</translation>
    </message>
    <message>
        <source>computing…</source>
        <translation>вычисление…</translation>
    </message>
    <message>
        <source>x (mm)</source>
        <translation>x (мм)</translation>
    </message>
    <message>
        <source>y (mm)</source>
        <translation>y (мм)</translation>
    </message>
    <message>
        <source>Workspace %1 · orientation range of φ from %2° to %3°</source>
        <translation>Рабочее пространство %1 · диапазон ориентации φ от %2° до %3°</translation>
    </message>
    <message>
        <source>orientation range of φ (°): the angles that hold the platform</source>
        <translation>диапазон ориентации φ (°): углы, в которых ноги удерживают платформу</translation>
    </message>
    <message>
        <source>At each point, the total width of the platform angles φ at which the legs can hold it there; the map&apos;s outline is the workspace at φ_map.</source>
        <translation>В каждой точке — суммарная ширина углов платформы φ, при которых ноги могут удерживать её там; контур карты — рабочее пространство при φ_map.</translation>
    </message>
    <message>
        <source>orientation range of φ</source>
        <translation>диапазон ориентации φ</translation>
    </message>
    <message>
        <source>force in the weakest direction</source>
        <translation>сила в самом слабом направлении</translation>
    </message>
    <message>
        <source>speed in the slowest direction</source>
        <translation>скорость в самом медленном направлении</translation>
    </message>
    <message>
        <source>worst resolution</source>
        <translation>наихудшая точность позиционирования</translation>
    </message>
    <message>
        <source>stiffness in the weakest direction</source>
        <translation>жёсткость в самом слабом направлении</translation>
    </message>
    <message>
        <source>where the requirements hold</source>
        <translation>где требования выполняются</translation>
    </message>
    <message>
        <source>Requirements met in %1 of the workspace %2 (%3 %)</source>
        <translation>Требования выполняются на %1 из рабочего пространства %2 (%3 %)</translation>
    </message>
    <message>
        <source>green: every requirement holds; grey: one fails</source>
        <translation>зелёный: выполняются все требования; серый: одно не выполняется</translation>
    </message>
    <message>
        <source>Required: %1</source>
        <translation>Требуется: %1</translation>
    </message>
    <message>
        <source>%1 (%2): %3, colours end at %4</source>
        <translation>%1 (%2): %3, цвета до %4</translation>
    </message>
    <message>
        <source>What the actuators deliver at each point of the workspace, from their limits in the design: 0 or ∞ exactly at a singularity. Every cell is the value of the pose solved there.</source>
        <translation>Что приводы обеспечивают в каждой точке рабочего пространства по своим пределам в конструкции: ровно 0 или ∞ в особом положении. Каждая ячейка — значение в положении, решённом в этой точке.</translation>
    </message>
    <message>
        <source>No requirements stated (Edit ▸ Requirements…): the whole workspace %1 meets them</source>
        <translation>Требования не заданы (Правка ▸ Требования…): всё рабочее пространство %1 им удовлетворяет</translation>
    </message>
    <message>
        <source>State what the actuators must deliver with Edit ▸ Requirements….</source>
        <translation>Задайте, что должны обеспечить приводы, в меню Правка ▸ Требования….</translation>
    </message>
    <message>
        <source>The first-order worst-case error of the platform point at each point of the workspace, from the tolerances of the Tolerances panel: ∞ at a direct singularity.</source>
        <translation>Наибольшая ошибка точки платформы в первом приближении в каждой точке рабочего пространства по допускам панели «Допуски»: ∞ в особом положении прямой кинематики.</translation>
    </message>
    <message>
        <source>worst-case error from the tolerances</source>
        <translation>наибольшая ошибка от допусков</translation>
    </message>
    <message>
        <source>Workspace %1 · %2 from %3 to %4%5 at the grid points</source>
        <translation>Рабочее пространство %1 · %2 от %3 до %4%5 в узлах сетки</translation>
    </message>
    <message>
        <source>%1 at φ = %2</source>
        <translation>%1 при φ = %2</translation>
    </message>
    <message>
        <source>Workspace %1 · %2 from %3 to %4 at the grid points</source>
        <translation>Рабочее пространство %1 · %2 от %3 до %4 в узлах сетки</translation>
    </message>
    <message>
        <source>%1 at φ = %2, not the pose&apos;s φ</source>
        <translation>%1 при φ = %2 (у текущего положения φ другой)</translation>
    </message>
    <message>
        <source>range of φ (°)</source>
        <translation>диапазон φ (°)</translation>
    </message>
    <message>
        <source>κ(J), log scale</source>
        <translation>κ(J), лог. шкала</translation>
    </message>
    <message>
        <source>Workspace %1</source>
        <translation>Рабочее пространство %1</translation>
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
        <translation>Сравнить рабочее пространство с:</translation>
    </message>
    <message>
        <source>Pin this design</source>
        <translation>Запомнить эту конструкцию</translation>
    </message>
    <message>
        <source>Keep the current design&apos;s workspace as the comparison, then change the design and see both outlines.</source>
        <translation>Оставить рабочее пространство текущей конструкции для сравнения, чтобы затем изменить конструкцию и увидеть оба контура.</translation>
    </message>
    <message>
        <source>nothing</source>
        <translation>ничем</translation>
    </message>
    <message>
        <source>pinned: %1</source>
        <translation>запомненная: %1</translation>
    </message>
    <message>
        <source>pinned</source>
        <translation>запомненная</translation>
    </message>
</context>
<context>
    <name>pkm::designfile</name>
    <message>
        <source>%1 is not valid JSON (%2 at byte %3).</source>
        <translation>%1 не является корректным JSON (%2 в байте %3).</translation>
    </message>
    <message>
        <source>%1 is not a PKM Studio design file.</source>
        <translation>%1 не является файлом конструкции PKM Studio.</translation>
    </message>
    <message>
        <source>%1 was written by a newer PKM Studio (format version %2; this version reads up to %3).</source>
        <translation>%1 записан более новой версией PKM Studio (версия формата %2; эта версия читает версии до %3).</translation>
    </message>
    <message>
        <source>%1 has no valid format version.</source>
        <translation>В %1 нет допустимой версии формата.</translation>
    </message>
    <message>
        <source>%1 names an unknown mechanism kind &apos;%2&apos;.</source>
        <translation>%1 указывает неизвестный тип механизма «%2».</translation>
    </message>
    <message>
        <source>%1: unknown parameter &apos;%2&apos;.</source>
        <translation>%1: неизвестный параметр «%2».</translation>
    </message>
    <message>
        <source>%1: parameter &apos;%2&apos; is not a number.</source>
        <translation>%1: параметр «%2» не является числом.</translation>
    </message>
    <message>
        <source>%1: parameter &apos;%2&apos; must be a number or one of %3, not &apos;%4&apos;.</source>
        <translation>%1: параметр «%2» должен быть числом или одним из значений %3, а не «%4».</translation>
    </message>
    <message>
        <source>%1: pose value &apos;%2&apos; is not a number.</source>
        <translation>%1: значение положения «%2» не является числом.</translation>
    </message>
    <message>
        <source>the pose&apos;s %1 = %2 %4 does not agree with its inputs, which give %3 %4.</source>
        <translation>значение положения %1 = %2 %4 не согласуется с входными координатами, которые дают %3 %4.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is neither a preset id (see &apos;pkm list&apos;) nor a design file.</source>
        <translation>«%1» не является ни идентификатором предустановки (см. «pkm list»), ни файлом конструкции.</translation>
    </message>
    <message>
        <source>Cannot open %1: %2.</source>
        <translation>Не удаётся открыть %1: %2.</translation>
    </message>
    <message>
        <source>Cannot write %1: %2.</source>
        <translation>Не удаётся записать %1: %2.</translation>
    </message>
    <message>
        <source>Unknown parameter &apos;%1&apos; (see &apos;pkm show&apos;).</source>
        <translation>Неизвестный параметр «%1» (см. «pkm show»).</translation>
    </message>
    <message>
        <source>Unknown pose variable &apos;%1&apos;.</source>
        <translation>Неизвестная переменная положения «%1».</translation>
    </message>
    <message>
        <source>Give either the actuated inputs or the outputs of the pose, not both.</source>
        <translation>Задайте либо приводные (входные), либо выходные координаты положения, но не те и другие вместе.</translation>
    </message>
    <message>
        <source>%1: “bookmarks” is not a list.</source>
        <translation>%1: «bookmarks» не является списком.</translation>
    </message>
    <message>
        <source>%1 has more than %2 bookmarks.</source>
        <translation>В %1 больше %2 закладок.</translation>
    </message>
    <message>
        <source>%1: a bookmark&apos;s name is longer than %2 characters.</source>
        <translation>%1: имя закладки длиннее %2 символов.</translation>
    </message>
    <message>
        <source>%1: bookmark “%2” has an invalid pose value &apos;%3&apos;.</source>
        <translation>%1: в закладке «%2» недопустимое значение положения «%3».</translation>
    </message>
    <message>
        <source>%1: “tolerances” is not an object.</source>
        <translation>%1: «tolerances» не является объектом.</translation>
    </message>
    <message>
        <source>%1 has more than %2 tolerances.</source>
        <translation>В %1 больше %2 допусков.</translation>
    </message>
    <message>
        <source>it is not a number</source>
        <translation>это не число</translation>
    </message>
    <message>
        <source>%1: the tolerance of &apos;%2&apos; is refused: %3</source>
        <translation>%1: допуск «%2» отклонён: %3</translation>
    </message>
    <message>
        <source>%1: “requirements” is not a list of texts.</source>
        <translation>%1: «requirements» — не список строк.</translation>
    </message>
    <message>
        <source>%1: “requirements” has more than %2 entries.</source>
        <translation>%1: в «requirements» больше %2 записей.</translation>
    </message>
    <message>
        <source>%1: “requirements” holds an entry that is not a text of at most %2 characters.</source>
        <translation>%1: в «requirements» есть запись, которая не является строкой длиной не более %2 символов.</translation>
    </message>
    <message>
        <source>%1: “requirements”: %2</source>
        <translation>%1: «requirements»: %2</translation>
    </message>
    <message>
        <source>%1 is larger than %2 MiB, the most a design file may be.</source>
        <translation>%1 больше %2 МиБ — наибольшего размера файла конструкции.</translation>
    </message>
    <message>
        <source>%1: the title is longer than %2 characters, the most a design keeps.</source>
        <translation>%1: название длиннее %2 символов — больше, чем хранит конструкция.</translation>
    </message>
    <message>
        <source>%1: the description is longer than %2 characters, the most a design keeps.</source>
        <translation>%1: описание длиннее %2 символов — больше, чем хранит конструкция.</translation>
    </message>
</context>
<context>
    <name>presets</name>
    <message>
        <source>Planar five-bar linkage (example)</source>
        <translation>Плоский пятизвенный механизм (пример)</translation>
    </message>
    <message>
        <source>Four-bar linkage example (crank-rocker 40/120/100/140 mm)</source>
        <translation>Пример четырёхзвенного механизма (кривошипно-коромысловый, 40/120/100/140 мм)</translation>
    </message>
    <message>
        <source>MOMA configuration 3a (γ₁ = −5°, γ₂ = +5°)</source>
        <translation>MOMA, конфигурация 3a (γ₁ = −5°, γ₂ = +5°)</translation>
    </message>
    <message>
        <source>Configuration of fig. 3a: R₁ = (−100, 0) mm, R₂ = (100, 0) mm, guides turned from the vertical by γ₁ = −5° and γ₂ = +5° (α_i = 270° + γ_i), so they open downwards. Links l₁ = l₂ = 195 mm, strokes h = 200 mm (p from 0 to 200 mm, measured from R_i along the guide). Both legs work with p_i = B_i − √(B_i² − C_i), the platform below the sliders. The document finds no direct singularities in this workspace.</source>
        <translation>Конфигурация рис. 3a: R₁ = (−100, 0) мм, R₂ = (100, 0) мм, направляющие повёрнуты от вертикали на γ₁ = −5° и γ₂ = +5° (α_i = 270° + γ_i), так что они расходятся книзу. Звенья l₁ = l₂ = 195 мм, ходы h = 200 мм (p от 0 до 200 мм, отсчитывается от R_i вдоль направляющей). Обе ноги работают с p_i = B_i − √(B_i² − C_i), платформа ниже ползунов. Документ не находит в этом рабочем пространстве особых положений прямой кинематики.</translation>
    </message>
    <message>
        <source>MOMA configuration 3b (γ₁ = +5°, γ₂ = −5°)</source>
        <translation>MOMA, конфигурация 3b (γ₁ = +5°, γ₂ = −5°)</translation>
    </message>
    <message>
        <source>Configuration of fig. 3b: as 3a with the guides turned the other way, γ₁ = +5° and γ₂ = −5°, so they close downwards. Links l₁ = l₂ = 195 mm, strokes h = 200 mm (p from 0 to 200 mm, measured from R_i along the guide). The document finds no direct singularities in this workspace.</source>
        <translation>Конфигурация рис. 3b: как 3a, но направляющие повёрнуты в другую сторону, γ₁ = +5° и γ₂ = −5°, так что они сходятся книзу. Звенья l₁ = l₂ = 195 мм, ходы h = 200 мм (p от 0 до 200 мм, отсчитывается от R_i вдоль направляющей). Документ не находит в этом рабочем пространстве особых положений прямой кинематики.</translation>
    </message>
    <message>
        <source>MOMA configuration 3c (interpreted)</source>
        <translation>MOMA, конфигурация 3c (интерпретация)</translation>
    </message>
    <message>
        <source>Interpreted: the document describes 3c in two ways that do not agree (the guides along the axes, or α = 225°/315° turned by β through the matrices (15–16)), and its figure is missing; this preset takes the first. Configuration of fig. 3c: R₁ = (250, 0) mm with α₁ = 180° and R₂ = (0, 250) mm with α₂ = 270°, the guides along the axes towards the corner. Links l₁ = l₂ = 195 mm, strokes h = 200 mm (p from 0 to 200 mm, measured from R_i along the guide). Here both legs take the document&apos;s root p_i = B_i − √…; every inverse singularity lies on x = 195 mm or y = 195 mm (a link perpendicular to its guide), where the document puts them, at the edge of the other assembly mode&apos;s region near (195, 195) mm; the direct singularity needs both slider joints at the origin, beyond the strokes.</source>
        <translation>Интерпретация: документ описывает 3c двумя несогласующимися способами (направляющие вдоль осей или α = 225°/315°, повёрнутые на β матрицами (15–16)), а рисунок отсутствует; эта предустановка берёт первый. Конфигурация рис. 3c: R₁ = (250, 0) мм с α₁ = 180° и R₂ = (0, 250) мм с α₂ = 270°, направляющие вдоль осей в сторону угла. Звенья l₁ = l₂ = 195 мм, ходы h = 200 мм (p от 0 до 200 мм, отсчитывается от R_i вдоль направляющей). Здесь обе ноги берут корень из документа p_i = B_i − √…; все особые положения обратной кинематики лежат на x = 195 мм или y = 195 мм (звено перпендикулярно своей направляющей), где их и указывает документ, на границе области другого варианта сборки около (195, 195) мм; для особого положения прямой кинематики оба шарнира ползунов должны оказаться в начале координат, за пределами ходов.</translation>
    </message>
    <message>
        <source>MOMA configuration 3d (interpreted)</source>
        <translation>MOMA, конфигурация 3d (интерпретация)</translation>
    </message>
    <message>
        <source>Interpreted: the document describes 3d in two ways that do not agree (the guides along the axes, or α = 225°/315° turned by β through the matrices (15–16)), and its figure is missing; this preset takes the first. Configuration of fig. 3d: R₁ = (117, 0) mm with α₁ = 0° and R₂ = (0, 117) mm with α₂ = 90°, the guides along the axes away from the corner, the platform between them near the origin. Links l₁ = l₂ = 195 mm, strokes h = 200 mm (p from 0 to 200 mm, measured from R_i along the guide). Here both legs take the root p_i = B_i + √… that keeps the platform on the corner side of the sliders; the direct singularities (links stretched in line) bound the workspace on the far side.</source>
        <translation>Интерпретация: документ описывает 3d двумя несогласующимися способами (направляющие вдоль осей или α = 225°/315°, повёрнутые на β матрицами (15–16)), а рисунок отсутствует; эта предустановка берёт первый. Конфигурация рис. 3d: R₁ = (117, 0) мм с α₁ = 0° и R₂ = (0, 117) мм с α₂ = 90°, направляющие вдоль осей в сторону от угла, платформа между ними около начала координат. Звенья l₁ = l₂ = 195 мм, ходы h = 200 мм (p от 0 до 200 мм, отсчитывается от R_i вдоль направляющей). Здесь обе ноги берут корень p_i = B_i + √…, при котором платформа остаётся со стороны угла относительно ползунов; особые положения прямой кинематики (звенья вытянуты в линию) ограничивают рабочее пространство с дальней стороны.</translation>
    </message>
    <message>
        <source>O-X glide prototype (l = 80 mm, s = 20 mm, L = 130 mm)</source>
        <translation>Прототип механизма O-X glide (l = 80 мм, s = 20 мм, L = 130 мм)</translation>
    </message>
    <message>
        <source>The rapid-prototyped O-X glide of the Novi Sad document: rods l = 80 mm, platform width s = 20 mm, transverse guides L = 130 mm (slider positions 0 to 130 mm), working in the extended (O) form. The guide spacing a = 15 mm and the longitudinal travel z = 0 to 150 mm are not given in the document and are chosen for the drawing; they do not change the planar workspace.</source>
        <translation>Механизм O-X glide из новисадского документа, изготовленный методом быстрого прототипирования: стержни l = 80 мм, ширина платформы s = 20 мм, поперечные направляющие L = 130 мм (положения ползунов от 0 до 130 мм), работа в вытянутой форме (O). Расстояние между направляющими a = 15 мм и продольный ход z от 0 до 150 мм в документе не указаны и выбраны для чертежа; на плоское рабочее пространство они не влияют.</translation>
    </message>
    <message>
        <source>П-joint laboratory prototype (a = 170 mm, k = 0.4)</source>
        <translation>Лабораторный прототип П-шарнира (a = 170 мм, k = 0,4)</translation>
    </message>
    <message>
        <source>The laboratory prototype of section 4.2: a = 170 mm, b = 68 mm (k = 0.4), θ = ±60°, driven by the hybrid stepper motor with integrated lead screw of Table 1 (lead 2.54 mm, 0.0127 mm/step, 50 mm/s, 130 N). The screw efficiency 0.4 is an assumption: Table 1 does not give it.</source>
        <translation>Лабораторный прототип из раздела 4.2: a = 170 мм, b = 68 мм (k = 0,4), θ = ±60°, привод — гибридный шаговый двигатель со встроенным ходовым винтом из табл. 1 (ход винта 2,54 мм, 0,0127 мм/шаг, 50 мм/с, 130 Н). КПД винта 0,4 принят как допущение: в табл. 1 он не указан.</translation>
    </message>
    <message>
        <source>П-joint design study k = 0.3 (a = 1 m)</source>
        <translation>Проектное исследование П-шарнира, k = 0,3 (a = 1 м)</translation>
    </message>
    <message>
        <source>Design study of figures 8–12: a = 1 m, k = 0.3, θ over ±75°, with the stepper motor of Table 1.</source>
        <translation>Проектное исследование по рис. 8–12: a = 1 м, k = 0,3, θ в пределах ±75°, с шаговым двигателем из табл. 1.</translation>
    </message>
    <message>
        <source>П-joint design study k = 0.4 (a = 1 m)</source>
        <translation>Проектное исследование П-шарнира, k = 0,4 (a = 1 м)</translation>
    </message>
    <message>
        <source>Design study of figures 8–12: a = 1 m, k = 0.4, θ over ±75°, with the stepper motor of Table 1.</source>
        <translation>Проектное исследование по рис. 8–12: a = 1 м, k = 0,4, θ в пределах ±75°, с шаговым двигателем из табл. 1.</translation>
    </message>
    <message>
        <source>П-joint design study k = 0.5 (a = 1 m)</source>
        <translation>Проектное исследование П-шарнира, k = 0,5 (a = 1 м)</translation>
    </message>
    <message>
        <source>Design study of figures 8–12: a = 1 m, k = 0.5, θ over ±75°, with the stepper motor of Table 1.</source>
        <translation>Проектное исследование по рис. 8–12: a = 1 м, k = 0,5, θ в пределах ±75°, с шаговым двигателем из табл. 1.</translation>
    </message>
    <message>
        <source>A classroom five-bar chosen for PKM Studio (the four-bar and mobility document of Khabibullina, Khabibullin and Islamov shows the planar five-bar in its fig. 1 without dimensions). Ground AE = 100 mm; cranks AB = DE = 80 mm, driven at A and at E and turning fully; distal links BC = CD = 120 mm, meeting at the output point C. Chebyshev&apos;s count W = 3·4 − 2·5 = 2: the two crank angles θ₁, θ₄ fix C. Working modes elbows out (B to the left of A→C, D to the right of E→C), assembly mode C above BD (to the left of B→D). At C = (50, 150) mm each distal link is nearly perpendicular to its crank and the distal links nearly perpendicular to each other, so κ(J) ≈ 1.11; the workspace of these modes is bounded by the legs stretched or folded in line and, low between A and E, by a direct singularity where BC and CD come in line.</source>
        <translation>Учебный пятизвенный механизм, подобранный для PKM Studio (документ Хабибуллиной, Хабибуллина и Исламова о четырёхзвенных механизмах и подвижности показывает плоский пятизвенный механизм на рис. 1 без размеров). Стойка AE = 100 мм; кривошипы AB = DE = 80 мм приводятся в A и в E и совершают полный оборот; дальние звенья BC = CD = 120 мм сходятся в выходной точке C. По формуле Чебышева W = 3·4 − 2·5 = 2: два угла кривошипов θ₁, θ₄ определяют положение C. Рабочие режимы «локтями наружу» (B слева от A→C, D справа от E→C), вариант сборки — C над BD (слева от B→D). При C = (50, 150) мм каждое дальнее звено почти перпендикулярно своему кривошипу, а дальние звенья почти перпендикулярны друг другу, поэтому κ(J) ≈ 1,11; рабочее пространство в этих режимах ограничено положениями, где ноги механизма вытянуты или сложены в линию, а внизу между A и E — особым положением прямой кинематики, где BC и CD оказываются на одной прямой.</translation>
    </message>
    <message>
        <source>An example crank-rocker chosen for PKM Studio: the four-bar document of Khabibullina, Khabibullin and Islamov gives no link lengths, so these are not the document&apos;s. Crank AB = 40 mm, coupler BC = 120 mm, rocker CD = 100 mm, ground AD = 140 mm: s + l = 180 mm &lt; p + q = 220 mm with the crank the shortest link, so the crank turns fully (α from 0° to 360°) and the rocker swings; the transmission angle stays between 53° and 110°. Open branch, ω₁ = 10 rad/s, coupler point M at the middle of BC.</source>
        <translation>Пример кривошипно-коромыслового механизма, подобранный для PKM Studio: документ Хабибуллиной, Хабибуллина и Исламова о четырёхзвенном механизме не даёт длин звеньев, поэтому эти размеры взяты не из документа. Кривошип AB = 40 мм, шатун BC = 120 мм, коромысло CD = 100 мм, стойка AD = 140 мм: s + l = 180 мм &lt; p + q = 220 мм, и кривошип — самое короткое звено, поэтому кривошип совершает полный оборот (α от 0° до 360°), а коромысло качается; угол передачи остаётся в пределах от 53° до 110°. Открытая ветвь, ω₁ = 10 рад/с, точка шатуна M в середине BC.</translation>
    </message>
    <message>
        <source>Planar parallel: MOMA configuration 3a from two P̲RR legs</source>
        <translation>Плоский параллельный: конфигурация MOMA 3a из двух ног P̲RR</translation>
    </message>
    <message>
        <source>MOMA configuration 3a (Vasilić and Živanović, the MOMA document, fig. 3a) rebuilt from the leg library: two P̲RR legs on guides from R₁ = (−100, 0) and R₂ = (100, 0) mm turned by γ = ∓5° from the vertical (α = 265°, 275°), strokes 0 to 200 mm, links 195 mm, both legs with q = B − √…, the platform right of C₁→C₂. Its poses and Jacobians are the MOMA kind&apos;s.</source>
        <translation>Конфигурация MOMA 3a (Василич и Живанович, документ о MOMA, рис. 3a), собранная из библиотеки ног: две ноги P̲RR на направляющих от R₁ = (−100, 0) и R₂ = (100, 0) мм, повёрнутых на γ = ∓5° от вертикали (α = 265°, 275°), ходы от 0 до 200 мм, звенья 195 мм, обе ноги с q = B − √…, платформа справа от C₁→C₂. Её позы и матрицы Якоби совпадают с позами и матрицами Якоби вида MOMA.</translation>
    </message>
    <message>
        <source>Planar parallel: a 3-RP̲R with six assembly modes</source>
        <translation>Плоский параллельный: 3-RP̲R с шестью режимами сборки</translation>
    </message>
    <message>
        <source>The 3-RP̲R of Innocenti and Parenti-Castelli, studied by Zein, Wenger and Chablat (Non-singular assembly-mode changing motions for 3-RPR parallel manipulators, Mechanism and Machine Theory, 2008): base joints A₁ = (0, 0), A₂ = (15.91, 0), A₃ = (0, 10), platform sides B₁B₂ = 17.04, B₂B₃ = 16.54, B₃B₁ = 20.84. At the strut lengths 14.98, 15.38 and 12 its direct kinematics has six real solutions.</source>
        <translation>Механизм 3-RP̲R Инноченти и Паренти-Кастелли, исследованный Зейном, Венгером и Шаблой (статья о переходах между режимами сборки 3-RP̲R без особых положений, журнал «Теория механизмов и машин», 2008): шарниры основания A₁ = (0; 0), A₂ = (15,91; 0), A₃ = (0; 10), стороны платформы B₁B₂ = 17,04, B₂B₃ = 16,54, B₃B₁ = 20,84. При длинах штанг 14,98; 15,38 и 12 его прямая кинематика имеет шесть вещественных решений.</translation>
    </message>
    <message>
        <source>Planar parallel: a symmetric 3-R̲RR</source>
        <translation>Плоский параллельный: симметричный 3-R̲RR</translation>
    </message>
    <message>
        <source>A symmetric 3-R̲RR chosen for PKM Studio, of the kind Gosselin and Angeles optimised (The optimum kinematic design of a planar three-degree-of-freedom parallel manipulator, 1988): base joints on an equilateral triangle of side 400 mm, cranks 120 mm, distal links 150 mm, an equilateral platform of circumradius 50 mm, every elbow left of A→P.</source>
        <translation>Симметричный 3-R̲RR, выбранный для PKM Studio, того вида, который оптимизировали Госселен и Анджелес (статья об оптимальном кинематическом синтезе плоского параллельного манипулятора с тремя степенями свободы, 1988): шарниры основания в вершинах равностороннего треугольника со стороной 400 мм, кривошипы 120 мм, дистальные звенья 150 мм, равносторонняя платформа с радиусом описанной окружности 50 мм, каждый локоть слева от A→P.</translation>
    </message>
    <message>
        <source>Planar parallel: a 5R driven by two П-joints</source>
        <translation>Плоский параллельный: 5R с приводом от двух П-шарниров</translation>
    </message>
    <message>
        <source>The planar 5R of the П-joint document&apos;s fig. 5 (Milutinović, Kokotović, Slavković and Živanović), each crank the crank of a laboratory П-joint (a = 170 mm, k = 0.4, θ = ±60°, diagonal 116.2 to 231.4 mm): pivots A₁ = (0, 0) and A₂ = (200, 0) mm, the П-joints&apos; bases turned by α = ±30°, distal links 200 mm.</source>
        <translation>Плоский 5R с рис. 5 документа о П-шарнире (Милутинович, Кокотович, Славкович и Живанович), каждый кривошип которого — кривошип лабораторного П-шарнира (a = 170 мм, k = 0.4, θ = ±60°, диагональ от 116.2 до 231.4 мм): опоры A₁ = (0, 0) и A₂ = (200, 0) мм, основания П-шарниров повёрнуты на α = ±30°, дистальные звенья 200 мм.</translation>
    </message>
    <message>
        <source>Planar parallel: the five-bar example from two R̲RR legs</source>
        <translation>Плоский параллельный: пример пятизвенника из двух ног R̲RR</translation>
    </message>
    <message>
        <source>The five-bar example rebuilt from the leg library (the four-bar and mobility document of Khabibullina, Khabibullin and Islamov, fig. 1): two R̲RR legs from A₁ = (0, 0) and A₂ = (100, 0) mm, cranks 80 mm, distal links 120 mm, elbows out, the platform point above the elbows. Its poses and Jacobians are the five-bar kind&apos;s.</source>
        <translation>Пример пятизвенника, собранный из библиотеки ног (документ о четырёхзвенном механизме и подвижности Хабибуллиной, Хабибуллина и Исламова, рис. 1): две ноги R̲RR от A₁ = (0, 0) и A₂ = (100, 0) мм, кривошипы 80 мм, дистальные звенья 120 мм, локти наружу, точка платформы над локтями. Его позы и матрицы Якоби совпадают с позами и матрицами Якоби вида пятизвенника.</translation>
    </message>
    <message>
        <source>Planar parallel: a translating platform driven by two П-joints</source>
        <translation>Плоский параллельный: поступательно движущаяся платформа с приводом от двух П-шарниров</translation>
    </message>
    <message>
        <source>The 2-DOF planar mechanism with a platform of constant orientation that Milutinović, Kokotović, Slavković and Živanović show among the applications of the П-joint (Механизам активног П-зглоба као еквивалента комбинације обртног зглоба и сегмента константне дужине, University of Belgrade, Faculty of Mechanical Engineering, 2014): two laboratory П-joints (a = 170 mm, k = 0.4, diagonal 116.5 to 231 mm) with their cranks at A₁ = (0, 0) and A₂ = (200, 0) mm and their bases turned by α = ±30°. The coupler of a П-joint keeps its direction, so a distal parallelogram of 200 mm from each coupler to the platform points B₁ = (−40, 0) and B₂ = (40, 0) mm keeps the platform&apos;s orientation. The second parallelogram repeats the first one&apos;s constraint: Chebyshev&apos;s count gives 1, the mobility is 2.</source>
        <translation>Плоский механизм с двумя степенями свободы и платформой постоянной ориентации, который Милутинович, Кокотович, Славкович и Живанович приводят среди применений П-шарнира («Механизм активного П-шарнира как эквивалент комбинации вращательного шарнира и сегмента постоянной длины», Белградский университет, машиностроительный факультет, 2014): два лабораторных П-шарнира (a = 170 мм, k = 0,4, диагональ от 116,5 до 231 мм) с кривошипами в A₁ = (0, 0) и A₂ = (200, 0) мм, основания которых повёрнуты на α = ±30°. Шатун П-шарнира сохраняет своё направление, поэтому дистальный параллелограмм длиной 200 мм от каждого шатуна к точкам платформы B₁ = (−40, 0) и B₂ = (40, 0) мм сохраняет ориентацию платформы. Второй параллелограмм повторяет связь первого: формула Чебышева даёт 1, а подвижность равна 2.</translation>
    </message>
    <message>
        <source>Planar parallel: a symmetric 3-P̲RR</source>
        <translation>Плоский параллельный: симметричный 3-P̲RR</translation>
    </message>
    <message>
        <source>A symmetric 3-P̲RR chosen for PKM Studio: three sliders driven along the sides of an equilateral triangle of side 346.41 mm (its corners A₁, A₂, A₃ 200 mm from the centre, each guide from Aᵢ towards the next corner, stroke 0 to 346.41 mm), distal links of 150 mm and an equilateral platform of circumradius 40 mm, every slider beyond the foot of the perpendicular from its platform point (working mode +1).</source>
        <translation>Симметричный 3-P̲RR, выбранный для PKM Studio: три ползуна с приводом вдоль сторон равностороннего треугольника со стороной 346.41 мм (его вершины A₁, A₂, A₃ в 200 мм от центра, каждая направляющая от Aᵢ к следующей вершине, ход от 0 до 346.41 мм), дистальные шатуны по 150 мм и равносторонняя платформа с радиусом описанной окружности 40 мм, каждый ползун за основанием перпендикуляра из своей точки платформы (рабочий режим +1).</translation>
    </message>
</context>
</TS>
