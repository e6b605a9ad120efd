<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_HK">
<context>
    <name>prisca::app::LanguageMenu</name>
    <message>
        <location filename="../app/LanguageMenu.cpp" line="40"/>
        <source>&amp;Language</source>
        <translation>語言(&amp;L)</translation>
    </message>
</context>
<context>
    <name>prisca::app::MainWindow</name>
    <message>
        <location filename="../app/MainWindow.cpp" line="80"/>
        <source>&amp;File</source>
        <translation>檔案(&amp;F)</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="81"/>
        <source>&amp;Quit</source>
        <translation>結束(&amp;Q)</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="82"/>
        <source>Close the window and leave PRISCA Lab</source>
        <translation>關閉視窗並離開 PRISCA Lab</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="83"/>
        <source>&amp;View</source>
        <translation>檢視(&amp;V)</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="84"/>
        <source>&amp;Help</source>
        <translation>說明(&amp;H)</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="85"/>
        <source>&amp;About PRISCA Lab</source>
        <translation>關於 PRISCA Lab(&amp;A)</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="86"/>
        <source>Show the version and what PRISCA Lab does</source>
        <translation>顯示版本及 PRISCA Lab 的用途</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="88"/>
        <source>Version %1</source>
        <translation>版本 %1</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="101"/>
        <source>Interface language: %1</source>
        <translation>介面語言：%1</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="113"/>
        <source>Teaches a robot to repeat one demonstrated manoeuvre precisely.</source>
        <translation>教機械人精準地重複一次示範過的動作。</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="115"/>
        <source>PRISCA (Policy Reasoning In State-and-Cost Adaptation) learns online from a single demonstration and a coarse sign model of the dynamics, such as &quot;steer left to turn left&quot;.</source>
        <translation>PRISCA（Policy Reasoning In State-and-Cost Adaptation）只需一次示範，加上一個粗略的動態正負號模型（例如「方向盤向左扭，車便向左轉」），便能在線學習。</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="119"/>
        <source>Built with Qt %1, running on Qt %2.</source>
        <translation>以 Qt %1 建置，現於 Qt %2 上執行。</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="122"/>
        <source>About PRISCA Lab</source>
        <translation>關於 PRISCA Lab</translation>
    </message>
</context>
<context>
    <name>prisca::app::WelcomePanel</name>
    <message>
        <location filename="../app/WelcomePanel.cpp" line="69"/>
        <source>Teach a robot to repeat one demonstrated manoeuvre</source>
        <translation>教機械人重複一次示範過的動作</translation>
    </message>
    <message>
        <location filename="../app/WelcomePanel.cpp" line="71"/>
        <source>Drive the robot through the manoeuvre once, on the lab floor or in simulation, while the ceiling camera or the simulator records what it does. PRISCA then learns from this single demonstration: it adjusts its controller online, trial after trial, until the robot repeats the manoeuvre precisely, even when the floor, the tyres or the starting position differ.</source>
        <translation>先在實驗室地面或模擬器中駕駛機械人完成一次動作，由天花板的攝影機或模擬器記錄整個過程。PRISCA 隨即從這一次示範中學習：在一次又一次的試驗中在線調整控制器，直至機械人能精準地重複該動作；即使地面、輪胎或起步位置有所不同，亦能做到。</translation>
    </message>
    <message>
        <location filename="../app/WelcomePanel.cpp" line="79"/>
        <source>Simulator: slide-car, acrobot and planar aircraft</source>
        <translation>模擬器：甩尾模型車、雙連桿擺臂（Acrobot）及平面飛行器</translation>
    </message>
    <message>
        <location filename="../app/WelcomePanel.cpp" line="80"/>
        <source>Recording: drive by keyboard or gamepad and record a demonstration</source>
        <translation>錄製：以鍵盤或手掣駕駛，錄製一次示範</translation>
    </message>
    <message>
        <location filename="../app/WelcomePanel.cpp" line="81"/>
        <source>Learning: fit the action mapping, run PRISCA or a baseline, and watch the tracking error live, with an emergency stop</source>
        <translation>學習：擬合動作映射，執行 PRISCA 或基準方法，並即時監察追蹤誤差，設有緊急停止</translation>
    </message>
    <message>
        <location filename="../app/WelcomePanel.cpp" line="83"/>
        <source>Evaluation: batches of trials, Table I metrics and learning curves</source>
        <translation>評估：批次試驗、表 I 指標及學習曲線</translation>
    </message>
    <message>
        <location filename="../app/WelcomePanel.cpp" line="86"/>
        <source>Arriving in coming versions:</source>
        <translation>以下功能將於往後版本推出：</translation>
    </message>
    <message>
        <location filename="../app/WelcomePanel.cpp" line="94"/>
        <source>This version has no working panels yet: nothing here records, learns or drives a robot.</source>
        <translation>此版本尚未有可用的操作面板：這裏不會錄製、學習或駕駛任何機械人。</translation>
    </message>
</context>
</TS>
