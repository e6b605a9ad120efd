<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_HK">
<context>
    <name>ActionMappingFit</name>
    <message>
        <location filename="../core/ActionMapping.cpp" line="170"/>
        <source>control &apos;%1&apos; never changed in the demonstration: its B_v entries stay 0 and it will not adapt; record a demonstration that uses it</source>
        <translation>控制「%1」在示範中從未改變：其 B_v 項保持為 0，不會自適應；請錄製一個有使用它的示範</translation>
    </message>
    <message>
        <location filename="../core/ActionMapping.cpp" line="211"/>
        <source>state &apos;%1&apos;: the controls acting on it moved together, so their shares cannot be told apart (minimum-norm fit)</source>
        <translation>狀態「%1」：作用於它的各控制一同變動，因此無法分辨各自的份額（最小範數擬合）</translation>
    </message>
    <message>
        <location filename="../core/ActionMapping.cpp" line="226"/>
        <source>&apos;%1&apos; moved &apos;%2&apos; the opposite way to the intuitive mapping (unconstrained B_v = %3)%4</source>
        <translation>「%1」令「%2」向直覺映射的相反方向變化（無約束 B_v = %3）%4</translation>
    </message>
    <message>
        <location filename="../core/ActionMapping.cpp" line="234"/>
        <source>; set to 0, check the sign or the demonstration</source>
        <translation>；已設為 0，請檢查符號或示範</translation>
    </message>
    <message>
        <location filename="../core/ActionMapping.cpp" line="237"/>
        <source>; check the sign or the demonstration</source>
        <translation>；請檢查符號或示範</translation>
    </message>
</context>
<context>
    <name>MethodParameter</name>
    <message>
        <location filename="../sim/methods/PriscaMethods.cpp" line="15"/>
        <source>Horizon H</source>
        <translation>時域 H</translation>
    </message>
    <message>
        <location filename="../sim/methods/PriscaMethods.cpp" line="16"/>
        <source>Smoothing horizon H of the nested expectation over the last H steps (eq. 9, 13).</source>
        <translation>巢狀期望在最近 H 步上的平滑時域 H（式 9、13）。</translation>
    </message>
    <message>
        <location filename="../sim/methods/PriscaMethods.cpp" line="31"/>
        <source>Depreciation γ</source>
        <translation>折舊 γ</translation>
    </message>
    <message>
        <location filename="../sim/methods/PriscaMethods.cpp" line="32"/>
        <source>Rate of inverse depreciation D (eq. 10); Lemma 4.1 needs γ ≥ 0.93 at H = 10.</source>
        <translation>逆折舊 D 的比率（式 10）；在 H = 10 時，引理 4.1 需要 γ ≥ 0.93。</translation>
    </message>
    <message>
        <location filename="../sim/methods/PriscaMethods.cpp" line="45"/>
        <source>Step rate β</source>
        <translation>步長速率 β</translation>
    </message>
    <message>
        <location filename="../sim/methods/PriscaMethods.cpp" line="46"/>
        <source>Rate of the decaying step size α_k = α_0 β / (k + β) (eq. 3).</source>
        <translation>遞減步長 α_k = α_0 β / (k + β) 的速率（式 3）。</translation>
    </message>
    <message>
        <location filename="../sim/methods/PriscaMethods.cpp" line="58"/>
        <source>Automatic scales</source>
        <translation>自動比例</translation>
    </message>
    <message>
        <location filename="../sim/methods/PriscaMethods.cpp" line="59"/>
        <source>Feature scales, α_0 and matching window derived from the demonstration and the fit when PRISCA starts; off: the step scale and feature scales set here.</source>
        <translation>PRISCA 開始時由示範及擬合推導特徵比例、α_0 及匹配窗口；關閉：使用此處設定的步長比例及特徵比例。</translation>
    </message>
    <message>
        <location filename="../sim/methods/FeedbackMethods.cpp" line="94"/>
        <source>Start</source>
        <translation>起點</translation>
    </message>
    <message>
        <location filename="../sim/methods/FeedbackMethods.cpp" line="95"/>
        <source>The feedback law the PD family and PRISCA (its prior) start from. tuned: the plant profile&apos;s PD gains; demo: derived from the demonstration, the fit and the actuator limits alone (a stationary LQR gain on the fitted model with weights from the demonstration&apos;s own scales, no faster than the fitted dead time allows, on the errors B~ names per control but those the action sets); PRISCA then also takes its automatic step and scales.</source>
        <translation>PD 系列及 PRISCA（其先驗）起始的回饋律。tuned：設備設定檔中調校好的 PD 增益；demo：只由示範、擬合及致動器限制推導（以示範本身的尺度為權重、在擬合模型上求得的穩態 LQR 增益，速度不超過擬合死區時間所容許，只用 B~ 為每個控制指明、而非由動作直接設定的誤差）；PRISCA 亦隨之採用自動步長及比例。</translation>
    </message>
    <message>
        <location filename="../sim/methods/PriscaMethods.cpp" line="88"/>
        <source>Step scale α_0</source>
        <translation>步長比例 α_0</translation>
    </message>
    <message>
        <location filename="../sim/methods/PriscaMethods.cpp" line="73"/>
        <source>Automatic α_0</source>
        <translation>自動 α_0</translation>
    </message>
    <message>
        <location filename="../sim/methods/PriscaMethods.cpp" line="75"/>
        <source>α_0 of the automatic scales: the fraction of a Newton step on the cost&apos;s curvature taken per control step.</source>
        <translation>自動尺度的 α_0：每個控制步按成本曲率所走的牛頓步比例。</translation>
    </message>
    <message>
        <location filename="../sim/methods/PriscaMethods.cpp" line="89"/>
        <source>α_0 of eq. 3 (the paper uses 1; its right size depends on the units of e, φ and B). Not used with automatic scales.</source>
        <translation>式 3 的 α_0（論文用 1；合適大小取決於 e、φ 及 B 的單位）。使用自動比例時不採用。</translation>
    </message>
    <message>
        <location filename="../sim/methods/PriscaMethods.cpp" line="102"/>
        <source>θ bound</source>
        <translation>θ 界限</translation>
    </message>
    <message>
        <location filename="../sim/methods/PriscaMethods.cpp" line="103"/>
        <source>If above 0, θ is kept in |θ_i| ≤ bound after each update (projected descent).</source>
        <translation>若大於 0，每次更新後 θ 保持在 |θ_i| ≤ 界限內（投影下降）。</translation>
    </message>
    <message>
        <location filename="../sim/methods/LearningMethods.cpp" line="47"/>
        <location filename="../sim/methods/PriscaMethods.cpp" line="106"/>
        <location filename="../sim/methods/PriscaMethods.cpp" line="157"/>
        <source>none</source>
        <translation>無</translation>
    </message>
    <message>
        <location filename="../sim/methods/PriscaMethods.cpp" line="117"/>
        <source>Start from the PD law</source>
        <translation>由 PD 控制律開始</translation>
    </message>
    <message>
        <location filename="../sim/methods/PriscaMethods.cpp" line="118"/>
        <source>The policy is u = u* + the PD law + θᵀφ, so θ = 0 already holds the robot on the path; off: θ = 0 is no feedback (Algorithm 1).</source>
        <translation>策略為 u = u* + PD 控制律 + θᵀφ，因此 θ = 0 已能讓機械人保持在路徑上；關閉：θ = 0 即無回饋（演算法 1）。</translation>
    </message>
    <message>
        <location filename="../sim/methods/PriscaMethods.cpp" line="131"/>
        <source>Gradient</source>
        <translation>梯度</translation>
    </message>
    <message>
        <location filename="../sim/methods/PriscaMethods.cpp" line="132"/>
        <source>one-step: eq. 14 as printed; closed-loop: eq. 4&apos;s chain rule carried over the window through the fitted model and the policy&apos;s own feedback.</source>
        <translation>one-step：照印出的式 14；closed-loop：式 4 的連鎖律經擬合模型及策略本身的回饋在窗口內傳遞。</translation>
    </message>
    <message>
        <location filename="../sim/methods/PriscaMethods.cpp" line="153"/>
        <source>Effort weight R</source>
        <translation>施力權重 R</translation>
    </message>
    <message>
        <location filename="../sim/methods/PriscaMethods.cpp" line="154"/>
        <source>The cost also charges the correction&apos;s effort, R (θᵀφ)² per control: what makes learning settle without a θ bound.</source>
        <translation>成本亦計入修正的施力，每個控制量 R (θᵀφ)²：令學習在無 θ 界限下收斂。</translation>
    </message>
    <message>
        <location filename="../sim/methods/PriscaMethods.cpp" line="176"/>
        <source>Local optimal baseline</source>
        <translation>局部最優基線</translation>
    </message>
    <message>
        <location filename="../sim/methods/PriscaMethods.cpp" line="177"/>
        <source>Subtract the local optimal baseline b (eq. 15) from the gradient; off: b = 0.</source>
        <translation>從梯度減去局部最優基線 b（式 15）；關閉：b = 0。</translation>
    </message>
    <message>
        <location filename="../sim/methods/PriscaMethods.cpp" line="192"/>
        <source>Inverse depreciation</source>
        <translation>逆折舊</translation>
    </message>
    <message>
        <location filename="../sim/methods/PriscaMethods.cpp" line="193"/>
        <source>Weigh the window&apos;s gradients by the inverse depreciation D (eq. 10); off: D = 1.</source>
        <translation>以逆折舊 D（式 10）加權窗口內的梯度；關閉：D = 1。</translation>
    </message>
    <message>
        <location filename="../sim/methods/PriscaMethods.cpp" line="210"/>
        <source>Model</source>
        <translation>模型</translation>
    </message>
    <message>
        <location filename="../sim/methods/PriscaMethods.cpp" line="211"/>
        <source>fitted: B = B_v (.) B~ from the fit (eq. 8); signs: B~ alone; drift: eq. 5 in full, the state&apos;s own drift A fitted with B.</source>
        <translation>fitted：擬合得出的 B = B_v (.) B~（式 8）；signs：只用 B~；drift：完整的式 5，狀態本身的漂移 A 與 B 一併擬合。</translation>
    </message>
    <message>
        <location filename="../sim/methods/PriscaMethods.cpp" line="228"/>
        <source>Model delay d</source>
        <translation>模型延遲 d</translation>
    </message>
    <message>
        <location filename="../sim/methods/PriscaMethods.cpp" line="230"/>
        <source>The measurement&apos;s age d in the closed-loop gradient&apos;s model.</source>
        <translation>閉環梯度模型中量測的時延 d。</translation>
    </message>
    <message>
        <location filename="../sim/methods/PriscaMethods.cpp" line="244"/>
        <source>Phase features</source>
        <translation>階段特徵</translation>
    </message>
    <message>
        <location filename="../sim/methods/PriscaMethods.cpp" line="245"/>
        <source>Length of the stretches of the demonstration over which PRISCA learns a correction of the demonstration&apos;s action (one feature per stretch and control); 0: none.</source>
        <translation>PRISCA 在示範中學習示範動作修正的每段長度（每段每個控制一個特徵）；0：不用。</translation>
    </message>
    <message>
        <location filename="../sim/methods/PriscaMethods.cpp" line="259"/>
        <source>Learn where explained</source>
        <translation>只在可解釋處學習</translation>
    </message>
    <message>
        <location filename="../sim/methods/PriscaMethods.cpp" line="260"/>
        <source>The closed-loop gradient learns only on the samples a robust fit explains.</source>
        <translation>閉環梯度只在穩健擬合能解釋的樣本上學習。</translation>
    </message>
    <message>
        <location filename="../sim/methods/FeedbackMethods.cpp" line="49"/>
        <source>Heading feedback reversed</source>
        <translation>倒車時反轉航向回饋</translation>
    </message>
    <message>
        <location filename="../sim/methods/FeedbackMethods.cpp" line="50"/>
        <source>For a vehicle, the feedback law (the PD family&apos;s, PRISCA&apos;s prior) turns the sign of its heading and yaw-rate terms where the demonstration drives backwards, where steering turns the car the other way; off: the same law in both directions.</source>
        <translation>對車輛而言，回饋律（PD 系列的、PRISCA 先驗的）在示範倒車之處反轉其航向及偏航率項的符號，因為該處轉向令車向另一邊轉；關閉：前進與倒車用同一回饋律。</translation>
    </message>
    <message>
        <location filename="../sim/methods/FeedbackMethods.cpp" line="68"/>
        <source>Feedback where explained</source>
        <translation>只在可解釋處回饋</translation>
    </message>
    <message>
        <location filename="../sim/methods/FeedbackMethods.cpp" line="69"/>
        <source>The feedback law (the PD family&apos;s, PRISCA&apos;s prior) acts only while the reference is a sample the robust fit explains: not in a slide, where the linear model the gains stand on does not hold. auto: with the demonstration start, not with the tuned one.</source>
        <translation>回饋律（PD 系列的、PRISCA 先驗的）只在參考樣本可被穩健擬合解釋時作用：滑行中不作用，因為增益所依據的線性模型在那裏不成立。auto：以示範起始時啟用，以調校起始時不啟用。</translation>
    </message>
    <message>
        <location filename="../sim/methods/FeedbackMethods.cpp" line="119"/>
        <source>Matching window</source>
        <translation>匹配窗口</translation>
    </message>
    <message>
        <location filename="../sim/methods/FeedbackMethods.cpp" line="121"/>
        <source>How far ahead the least-state-deviation reference may search (eq. 12); 0 searches the whole demonstration.</source>
        <translation>最小狀態偏差參考點可向前搜尋的範圍（式 12）；0 表示搜尋整段示範。</translation>
    </message>
    <message>
        <location filename="../sim/methods/FeedbackMethods.cpp" line="136"/>
        <source>PD gain Kp</source>
        <translation>PD 增益 Kp</translation>
    </message>
    <message>
        <location filename="../sim/methods/FeedbackMethods.cpp" line="137"/>
        <source>Proportional gain per control on its error combination c_l · e (u = u* − Kp ε − Kd dε/dt).</source>
        <translation>每個控制量對其誤差組合 c_l · e 的比例增益（u = u* − Kp ε − Kd dε/dt）。</translation>
    </message>
    <message>
        <location filename="../sim/methods/FeedbackMethods.cpp" line="151"/>
        <source>PD gain Kd</source>
        <translation>PD 增益 Kd</translation>
    </message>
    <message>
        <location filename="../sim/methods/FeedbackMethods.cpp" line="152"/>
        <source>Derivative gain per control on the rate of its error combination.</source>
        <translation>每個控制量對其誤差組合變化率的微分增益。</translation>
    </message>
    <message>
        <location filename="../sim/methods/FeedbackMethods.cpp" line="166"/>
        <source>PD smoothing H</source>
        <translation>PD 平滑 H</translation>
    </message>
    <message>
        <location filename="../sim/methods/FeedbackMethods.cpp" line="167"/>
        <source>PD+H and PD+H+LSD smooth the error over this many steps (the weights of eq. 9).</source>
        <translation>PD+H 及 PD+H+LSD 在這麼多步上平滑誤差（式 9 的權重）。</translation>
    </message>
    <message>
        <location filename="../sim/methods/LearningMethods.cpp" line="18"/>
        <source>PGSD horizon H</source>
        <translation>PGSD 時域 H</translation>
    </message>
    <message>
        <location filename="../sim/methods/LearningMethods.cpp" line="19"/>
        <source>PGSD&apos;s smoothing horizon H (eq. 9).</source>
        <translation>PGSD 的平滑時域 H（式 9）。</translation>
    </message>
    <message>
        <location filename="../sim/methods/LearningMethods.cpp" line="32"/>
        <source>PGSD step α</source>
        <translation>PGSD 步長 α</translation>
    </message>
    <message>
        <location filename="../sim/methods/LearningMethods.cpp" line="33"/>
        <source>The fixed step size of PGSD (no decay).</source>
        <translation>PGSD 的固定步長（不遞減）。</translation>
    </message>
    <message>
        <location filename="../sim/methods/LearningMethods.cpp" line="44"/>
        <source>PGSD θ bound</source>
        <translation>PGSD θ 界限</translation>
    </message>
    <message>
        <location filename="../sim/methods/LearningMethods.cpp" line="45"/>
        <source>If above 0, PGSD&apos;s θ is kept in |θ_i| ≤ bound after each update.</source>
        <translation>若大於 0，每次更新後 PGSD 的 θ 保持在 |θ_i| ≤ 界限內。</translation>
    </message>
    <message>
        <location filename="../sim/methods/LearningMethods.cpp" line="58"/>
        <source>PEGASUS iterations</source>
        <translation>PEGASUS 迭代次數</translation>
    </message>
    <message>
        <location filename="../sim/methods/LearningMethods.cpp" line="60"/>
        <source>Gradient steps PEGASUS takes on its fixed scenarios before a run.</source>
        <translation>PEGASUS 在運行前於其固定情境上所作的梯度步數。</translation>
    </message>
    <message>
        <location filename="../sim/methods/LearningMethods.cpp" line="74"/>
        <source>PEGASUS scenarios</source>
        <translation>PEGASUS 情境數</translation>
    </message>
    <message>
        <location filename="../sim/methods/LearningMethods.cpp" line="76"/>
        <source>Fixed scenarios (start, perturbation, noise) each evaluation averages.</source>
        <translation>每次評估所平均的固定情境（起點、擾動、雜訊）數目。</translation>
    </message>
    <message>
        <location filename="../sim/methods/LearningMethods.cpp" line="91"/>
        <source>PEGASUS step α</source>
        <translation>PEGASUS 步長 α</translation>
    </message>
    <message>
        <location filename="../sim/methods/LearningMethods.cpp" line="92"/>
        <source>Gradient-descent step on the mean episode cost.</source>
        <translation>對平均回合成本的梯度下降步長。</translation>
    </message>
    <message>
        <location filename="../sim/methods/LearningMethods.cpp" line="104"/>
        <source>ILC learning Γ/Kp</source>
        <translation>ILC 學習 Γ/Kp</translation>
    </message>
    <message>
        <location filename="../sim/methods/LearningMethods.cpp" line="106"/>
        <source>ILC&apos;s learning gain per control, as a share of the PD&apos;s Kp: how much of a trial&apos;s error goes into the next trial&apos;s feedforward.</source>
        <translation>ILC 每個控制量的學習增益，以 PD 的 Kp 的比例表示：一次試驗的誤差有多少會計入下一次試驗的前饋。</translation>
    </message>
    <message>
        <location filename="../sim/methods/LearningMethods.cpp" line="119"/>
        <source>ILC lead</source>
        <translation>ILC 超前</translation>
    </message>
    <message>
        <location filename="../sim/methods/LearningMethods.cpp" line="120"/>
        <source>The error this many steps later corrects the action now (covers the plant&apos;s delay).</source>
        <translation>以這麼多步之後的誤差修正現在的動作（補償對象的延遲）。</translation>
    </message>
    <message>
        <location filename="../sim/methods/LearningMethods.cpp" line="135"/>
        <source>ILC Q cutoff</source>
        <translation>ILC Q 截止頻率</translation>
    </message>
    <message>
        <location filename="../sim/methods/LearningMethods.cpp" line="136"/>
        <source>Zero-phase low-pass on the learned feedforward after each trial; 0 leaves it unfiltered.</source>
        <translation>每次試驗後對學到的前饋作零相位低通濾波；0 表示不濾波。</translation>
    </message>
    <message>
        <location filename="../sim/methods/LearningMethods.cpp" line="149"/>
        <source>ILC feedback scale</source>
        <translation>ILC 回饋比例</translation>
    </message>
    <message>
        <location filename="../sim/methods/LearningMethods.cpp" line="150"/>
        <source>The PD gains in ILC&apos;s loop, scaled by this.</source>
        <translation>ILC 迴路中的 PD 增益以此比例縮放。</translation>
    </message>
    <message>
        <location filename="../sim/methods/PlanningMethods.cpp" line="35"/>
        <source>Oracle samples</source>
        <translation>理想控制器樣本數</translation>
    </message>
    <message>
        <location filename="../sim/methods/PlanningMethods.cpp" line="36"/>
        <source>Candidate plans the oracle simulates at each planning.</source>
        <translation>理想控制器每次規劃時模擬的候選方案數目。</translation>
    </message>
    <message>
        <location filename="../sim/methods/PlanningMethods.cpp" line="50"/>
        <source>Oracle replanning</source>
        <translation>理想控制器重新規劃</translation>
    </message>
    <message>
        <location filename="../sim/methods/PlanningMethods.cpp" line="52"/>
        <source>Control steps between two plans of the oracle.</source>
        <translation>理想控制器兩次規劃之間的控制步數。</translation>
    </message>
    <message>
        <location filename="../sim/methods/PlanningMethods.cpp" line="65"/>
        <source>Replanning</source>
        <translation>重新規劃</translation>
    </message>
    <message>
        <location filename="../sim/methods/PlanningMethods.cpp" line="66"/>
        <source>Control steps between two plans through the model (2 at 25 Hz: every 0.08 s).</source>
        <translation>兩次經模型規劃之間的控制步數（25 Hz 時為 2：每 0.08 秒）。</translation>
    </message>
    <message>
        <location filename="../sim/methods/PlanningMethods.cpp" line="81"/>
        <source>Model runs per plan</source>
        <translation>每次規劃的模型模擬次數</translation>
    </message>
    <message>
        <location filename="../sim/methods/PlanningMethods.cpp" line="83"/>
        <source>The planning&apos;s budget: runs of the model to the trial&apos;s end per plan.</source>
        <translation>規劃的預算：每次規劃把模型模擬到試驗結束的次數。</translation>
    </message>
    <message>
        <location filename="../sim/methods/PlanningMethods.cpp" line="98"/>
        <source>Predicted tube</source>
        <translation>預測管道</translation>
    </message>
    <message>
        <location filename="../sim/methods/PlanningMethods.cpp" line="99"/>
        <source>How far the measured position may stray from the model&apos;s prediction before the fallback law finishes the trial.</source>
        <translation>量得的位置可偏離模型預測多遠，超出後由後備控制律完成該次試驗。</translation>
    </message>
    <message>
        <location filename="../sim/methods/PlanningMethods.cpp" line="112"/>
        <source>Model good enough to plan</source>
        <translation>模型足以規劃</translation>
    </message>
    <message>
        <location filename="../sim/methods/PlanningMethods.cpp" line="114"/>
        <source>How closely the model must fit its data to be planned through; a model that fits worse leaves the whole trial to the feedback law.</source>
        <translation>模型須與其數據吻合到多近才可據以規劃；吻合得更差的模型，整次試驗交由回饋控制律駕駛。</translation>
    </message>
    <message>
        <location filename="../sim/methods/PlanningMethods.cpp" line="128"/>
        <source>Corrections before the turn</source>
        <translation>轉彎前的修正</translation>
    </message>
    <message>
        <location filename="../sim/methods/PlanningMethods.cpp" line="130"/>
        <source>The largest change the plan makes to the demonstration&apos;s actions before its turn, as a share of each action&apos;s half range (2: no bound).</source>
        <translation>計劃在示範轉彎之前對其動作所作的最大改動，以每個動作半幅度的比例表示（2：不設限）。</translation>
    </message>
    <message>
        <location filename="../sim/methods/PlanningMethods.cpp" line="144"/>
        <source>Rolling correction</source>
        <translation>滾動阻力修正</translation>
    </message>
    <message>
        <location filename="../sim/methods/PlanningMethods.cpp" line="146"/>
        <source>While the car parks, how fast the model&apos;s rolling resistance follows the deceleration it failed to predict (0: never).</source>
        <translation>泊車期間，模型的滾動阻力跟隨其未能預測的減速度的快慢（0：從不）。</translation>
    </message>
    <message>
        <location filename="../sim/methods/PlanningMethods.cpp" line="159"/>
        <source>Steering correction</source>
        <translation>轉向修正</translation>
    </message>
    <message>
        <location filename="../sim/methods/PlanningMethods.cpp" line="161"/>
        <source>On the way into the slide, how fast the model&apos;s steering offset follows the heading it failed to predict: a trim the car has and the model has not (0: never).</source>
        <translation>進入滑行途中，模型的轉向偏移跟隨其未能預測的車頭方向的速度：即車有而模型沒有的微調偏差（0：從不）。</translation>
    </message>
    <message>
        <location filename="../sim/methods/PlanningMethods.cpp" line="175"/>
        <source>Spin guard</source>
        <translation>打轉防護</translation>
    </message>
    <message>
        <location filename="../sim/methods/PlanningMethods.cpp" line="177"/>
        <source>How far the side-slip angle may stray from the demonstration&apos;s on the way into the slide before the fallback law finishes the trial (0: no guard).</source>
        <translation>進入滑行途中，側滑角可偏離示範的側滑角多遠，超出後由後備控制律完成該次試驗（0：不設防護）。</translation>
    </message>
    <message>
        <location filename="../sim/methods/PlanningMethods.cpp" line="195"/>
        <source>Model fit&apos;s segments</source>
        <translation>模型擬合的分段</translation>
    </message>
    <message>
        <location filename="../sim/methods/PlanningMethods.cpp" line="197"/>
        <source>How long a stretch of the data the model is fitted to predict from each recorded state (identification&apos;s segment).</source>
        <translation>模型由每個記錄狀態起須預測的數據片段長度（辨識的分段）。</translation>
    </message>
    <message>
        <location filename="../sim/methods/PlanningMethods.cpp" line="210"/>
        <source>Parking hand-over</source>
        <translation>泊車交接</translation>
    </message>
    <message>
        <location filename="../sim/methods/PlanningMethods.cpp" line="212"/>
        <source>Past the demonstration&apos;s fastest turn, the feedback law parks the car once it is slower than this (0: the plan drives to the end).</source>
        <translation>越過示範最急的轉彎後，車速低於此值時由回饋控制律泊車（0：由規劃一直駕駛到完結）。</translation>
    </message>
    <message>
        <location filename="../sim/methods/PlanningMethods.cpp" line="226"/>
        <source>Hand-over near the lot</source>
        <translation>近車位先交接</translation>
    </message>
    <message>
        <location filename="../sim/methods/PlanningMethods.cpp" line="228"/>
        <source>The parking hand-over waits until the car is this close to the lot; farther away the plan drives on (0: at any distance).</source>
        <translation>泊車交接要等車駛到離車位這個距離以內；離得更遠時由規劃繼續駕駛（0：任何距離都交接）。</translation>
    </message>
    <message>
        <location filename="../sim/methods/PlanningMethods.cpp" line="241"/>
        <source>Approach to the lot</source>
        <translation>駛近車位</translation>
    </message>
    <message>
        <location filename="../sim/methods/PlanningMethods.cpp" line="243"/>
        <source>Once the feedback law parks the car, a car that would coast to rest more than this short of the lot is driven on towards it (0: off, the law&apos;s throttle).</source>
        <translation>回授律停車時，若車滑行停下的位置會比車位短超過此距離，就繼續推車駛向車位（0：關閉，用回授律的油門）。</translation>
    </message>
    <message>
        <location filename="../sim/methods/PlanningMethods.cpp" line="257"/>
        <source>Slide worth planning</source>
        <translation>值得規劃的滑行</translation>
    </message>
    <message>
        <location filename="../sim/methods/PlanningMethods.cpp" line="259"/>
        <source>A demonstration whose largest sideways speed is under this is driven by the feedback law, not planned through (0: every slide is planned).</source>
        <translation>示範的最大側向速度低於此值時，由回饋控制律駕駛，不經模型規劃（0：每次滑行都規劃）。</translation>
    </message>
    <message>
        <location filename="../sim/methods/PlanningMethods.cpp" line="273"/>
        <source>Refit after each trial</source>
        <translation>每次試驗後重新擬合</translation>
    </message>
    <message>
        <location filename="../sim/methods/PlanningMethods.cpp" line="274"/>
        <source>Refit the model on the demonstration and the day&apos;s newest trials after each trial.</source>
        <translation>每次試驗後，用示範及當日最新的試驗重新擬合模型。</translation>
    </message>
    <message>
        <location filename="../sim/methods/PlanningMethods.cpp" line="288"/>
        <source>Start law learns across trials</source>
        <translation>起始控制律跨試驗學習</translation>
    </message>
    <message>
        <location filename="../sim/methods/PlanningMethods.cpp" line="289"/>
        <source>The feedback law that drives a trial not planned through (ILC&apos;s loop) learns from the day&apos;s trials it drove.</source>
        <translation>驅動未經規劃試驗的回饋控制律（ILC 迴路）會從當日由它駕駛的試驗中學習。</translation>
    </message>
    <message>
        <location filename="../sim/methods/PlanningMethods.cpp" line="302"/>
        <source>Day&apos;s trials choose the law</source>
        <translation>由當日試驗選擇控制律</translation>
    </message>
    <message>
        <location filename="../sim/methods/PlanningMethods.cpp" line="303"/>
        <source>Once the start law&apos;s trials park farther than the plan&apos;s bound on average, the next trial not planned through is the fallback law&apos;s (PD+LSD) from its start, and from then on the one of the two that has parked the day&apos;s trials closer drives them.</source>
        <translation>起始控制律的試驗平均停得比計劃的界限更遠時，下一次未經規劃的試驗由後備控制律（PD+LSD）從頭駕駛；此後由兩者中當日試驗平均停得較近的一方駕駛。</translation>
    </message>
    <message>
        <location filename="../sim/methods/PlanningMethods.cpp" line="319"/>
        <source>Plan kept while it parks within</source>
        <translation>計劃停車誤差上限</translation>
    </message>
    <message>
        <location filename="../sim/methods/PlanningMethods.cpp" line="321"/>
        <source>Once a planned trial parks farther than this from the lot, the next trial is the feedback law&apos;s, and from then on each trial goes to whichever has parked the day&apos;s trials closer (0: the plan drives every trial it may).</source>
        <translation>按計劃駕駛的試驗一旦停在離車位超過此距離之處，下一次試驗交由回饋律駕駛；此後每次試驗交給當日試驗平均停得較近的一方（0：計劃駕駛每次可駕駛的試驗）。</translation>
    </message>
    <message>
        <location filename="../sim/methods/LqrMethod.cpp" line="20"/>
        <source>LQR effort weight R</source>
        <translation>LQR 施力權重 R</translation>
    </message>
    <message>
        <location filename="../sim/methods/LqrMethod.cpp" line="22"/>
        <source>R per control in the LQR&apos;s cost e^T W e + (u − u*)^T R (u − u*): larger is gentler.</source>
        <translation>LQR 成本 e^T W e + (u − u*)^T R (u − u*) 中每個控制量的 R：越大越溫和。</translation>
    </message>
    <message>
        <location filename="../sim/methods/LqrMethod.cpp" line="36"/>
        <source>LQR terminal weight</source>
        <translation>LQR 終端權重</translation>
    </message>
    <message>
        <location filename="../sim/methods/LqrMethod.cpp" line="38"/>
        <source>The deviation at the demonstration&apos;s end costs this many times a step&apos;s (where a parking manoeuvre is judged).</source>
        <translation>示範結束時的偏差成本為每步的這麼多倍（泊車動作在此評定）。</translation>
    </message>
    <message>
        <location filename="../sim/methods/LqrMethod.cpp" line="51"/>
        <source>LQR models the drift</source>
        <translation>LQR 模型包含漂移</translation>
    </message>
    <message>
        <location filename="../sim/methods/LqrMethod.cpp" line="52"/>
        <source>Fit eq. 5 in full (the state&apos;s own drift A with B); off: B alone, each state driven only by the controls.</source>
        <translation>完整擬合式 5（狀態本身的漂移 A 連同 B）；關閉：只用 B，每個狀態只受控制量驅動。</translation>
    </message>
</context>
<context>
    <name>OperatorText</name>
    <message>
        <location filename="../app/OperatorText.cpp" line="27"/>
        <source>%1 s</source>
        <translation>%1 秒</translation>
    </message>
    <message>
        <location filename="../app/OperatorText.cpp" line="30"/>
        <source>%1 min %2 s</source>
        <translation>%1 分 %2 秒</translation>
    </message>
    <message>
        <location filename="../app/OperatorText.cpp" line="34"/>
        <source>%1 h %2 min</source>
        <translation>%1 小時 %2 分</translation>
    </message>
    <message>
        <location filename="../app/OperatorText.cpp" line="43"/>
        <source>about %1 left</source>
        <translation>約剩 %1</translation>
    </message>
    <message>
        <location filename="../app/OperatorText.cpp" line="45"/>
        <source>estimating the time left</source>
        <translation>正在估算剩餘時間</translation>
    </message>
    <message>
        <location filename="../app/OperatorText.cpp" line="46"/>
        <source>%1 so far · %2</source>
        <translation>已用 %1 · %2</translation>
    </message>
</context>
<context>
    <name>PaperFigures</name>
    <message>
        <location filename="../app/figures/PaperFigures.cpp" line="41"/>
        <source>Slide parking: every trial&apos;s path and end posture (lot dashed red)</source>
        <translation>滑行泊車：每次試驗的路徑與最終姿態（車位為紅色虛線）</translation>
    </message>
    <message>
        <location filename="../app/figures/PaperFigures.cpp" line="58"/>
        <source>: close-up of the lot</source>
        <translation>：車位特寫</translation>
    </message>
    <message>
        <location filename="../app/figures/PaperFigures.cpp" line="60"/>
        <source>x [cm]</source>
        <translation>x [cm]</translation>
    </message>
    <message>
        <location filename="../app/figures/PaperFigures.cpp" line="61"/>
        <source>y [cm]</source>
        <translation>y [cm]</translation>
    </message>
    <message>
        <location filename="../app/figures/PaperFigures.cpp" line="104"/>
        <source>Learning curves: mean and 95% band</source>
        <translation>學習曲線：平均值與 95% 區間</translation>
    </message>
    <message>
        <location filename="../app/figures/PaperFigures.cpp" line="105"/>
        <source>simulated experience [s]</source>
        <translation>模擬經驗 [s]</translation>
    </message>
    <message>
        <location filename="../app/figures/PaperFigures.cpp" line="133"/>
        <source>Lemma 4.1: Var(D) over τ&apos; = 2H steps</source>
        <translation>引理 4.1：τ&apos; = 2H 步內的 Var(D)</translation>
    </message>
    <message>
        <location filename="../app/figures/PaperFigures.cpp" line="167"/>
        <source>%1: RMS %2 m in time, %3 m to the path (mean of %4)</source>
        <translation>%1：按時間 RMS %2 m，距路徑 %3 m（%4 次的平均）</translation>
    </message>
    <message>
        <location filename="../app/figures/PaperFigures.cpp" line="173"/>
        <source>x [m]</source>
        <translation>x [m]</translation>
    </message>
    <message>
        <location filename="../app/figures/PaperFigures.cpp" line="174"/>
        <source>y [m]</source>
        <translation>y [m]</translation>
    </message>
</context>
<context>
    <name>PlantCatalog</name>
    <message>
        <location filename="../sim/PlantCatalog.cpp" line="29"/>
        <source>Simulated slide-car</source>
        <translation>模擬漂移車</translation>
    </message>
    <message>
        <location filename="../sim/PlantCatalog.cpp" line="39"/>
        <source>Simulated acrobot</source>
        <translation>模擬雙擺機械臂</translation>
    </message>
    <message>
        <location filename="../sim/PlantCatalog.cpp" line="49"/>
        <source>Simulated aircraft</source>
        <translation>模擬飛機</translation>
    </message>
    <message>
        <location filename="../sim/PlantCatalog.cpp" line="59"/>
        <source>Simulated differential-drive robot</source>
        <translation>模擬差速驅動機械人</translation>
    </message>
</context>
<context>
    <name>PlantControl</name>
    <message>
        <location filename="../app/OperatorText.cpp" line="12"/>
        <source>throttle</source>
        <translation>油門</translation>
    </message>
    <message>
        <location filename="../app/OperatorText.cpp" line="13"/>
        <source>steering</source>
        <translation>轉向</translation>
    </message>
    <message>
        <location filename="../app/OperatorText.cpp" line="14"/>
        <source>rudder</source>
        <translation>方向舵</translation>
    </message>
    <message>
        <location filename="../app/OperatorText.cpp" line="15"/>
        <source>left wheel</source>
        <translation>左輪</translation>
    </message>
    <message>
        <location filename="../app/OperatorText.cpp" line="16"/>
        <source>right wheel</source>
        <translation>右輪</translation>
    </message>
</context>
<context>
    <name>prisca::app::ArenaView</name>
    <message>
        <location filename="../app/widgets/ArenaView.cpp" line="251"/>
        <source>desired</source>
        <translation>期望</translation>
    </message>
    <message>
        <location filename="../app/widgets/ArenaView.cpp" line="252"/>
        <source>actual</source>
        <translation>實際</translation>
    </message>
    <message>
        <location filename="../app/widgets/ArenaView.cpp" line="280"/>
        <source>%1 cm</source>
        <translation>%1 厘米</translation>
    </message>
    <message>
        <location filename="../app/widgets/ArenaView.cpp" line="281"/>
        <source>%1 m</source>
        <translation>%1 米</translation>
    </message>
    <message>
        <location filename="../app/widgets/ArenaView.cpp" line="513"/>
        <source>wind %1 m/s</source>
        <translation>風速 %1 米/秒</translation>
    </message>
</context>
<context>
    <name>prisca::app::BundleChooser</name>
    <message>
        <location filename="../app/widgets/BundleChooser.cpp" line="62"/>
        <source>incomplete</source>
        <translation>不完整</translation>
    </message>
    <message>
        <location filename="../app/widgets/BundleChooser.cpp" line="64"/>
        <source>failsafe: %1</source>
        <translation>失效保護：%1</translation>
    </message>
    <message>
        <location filename="../app/widgets/BundleChooser.cpp" line="66"/>
        <source>parked %1 cm</source>
        <translation>停在 %1 厘米處</translation>
    </message>
    <message>
        <location filename="../app/widgets/BundleChooser.cpp" line="69"/>
        <source>stopped</source>
        <translation>已停止</translation>
    </message>
    <message>
        <location filename="../app/widgets/BundleChooser.cpp" line="82"/>
        <location filename="../app/widgets/BundleChooser.cpp" line="134"/>
        <source>Replay a trial bundle</source>
        <translation>重播試驗包</translation>
    </message>
    <message>
        <location filename="../app/widgets/BundleChooser.cpp" line="85"/>
        <source>Started</source>
        <translation>開始時間</translation>
    </message>
    <message>
        <location filename="../app/widgets/BundleChooser.cpp" line="85"/>
        <source>Method</source>
        <translation>方法</translation>
    </message>
    <message>
        <location filename="../app/widgets/BundleChooser.cpp" line="85"/>
        <source>Trial</source>
        <translation>試驗</translation>
    </message>
    <message>
        <location filename="../app/widgets/BundleChooser.cpp" line="85"/>
        <source>Outcome</source>
        <translation>結果</translation>
    </message>
    <message>
        <location filename="../app/widgets/BundleChooser.cpp" line="103"/>
        <source>Trials on the rig (%1)</source>
        <translation>實機試驗（%1）</translation>
    </message>
    <message>
        <location filename="../app/widgets/BundleChooser.cpp" line="104"/>
        <source>Simulated trials (%1)</source>
        <translation>模擬試驗（%1）</translation>
    </message>
    <message>
        <location filename="../app/widgets/BundleChooser.cpp" line="121"/>
        <source>No trial bundles yet in %1.</source>
        <translation>%1 尚未有試驗包。</translation>
    </message>
    <message>
        <location filename="../app/widgets/BundleChooser.cpp" line="126"/>
        <source>Other folder...</source>
        <translation>其他資料夾……</translation>
    </message>
</context>
<context>
    <name>prisca::app::CameraView</name>
    <message>
        <location filename="../app/widgets/CameraView.cpp" line="97"/>
        <source>No camera image</source>
        <translation>沒有攝影機影像</translation>
    </message>
    <message>
        <location filename="../app/widgets/CameraView.cpp" line="174"/>
        <source>x %1 m, y %2 m, heading %3°</source>
        <translation>x %1 米，y %2 米，航向 %3°</translation>
    </message>
    <message>
        <location filename="../app/widgets/CameraView.cpp" line="178"/>
        <source>no pose (failsafe)</source>
        <translation>沒有位姿（失效保護）</translation>
    </message>
    <message>
        <location filename="../app/widgets/CameraView.cpp" line="183"/>
        <source>Calibrating: click a floor point whose position you know</source>
        <translation>校準中：點擊一個已知位置的地面點</translation>
    </message>
</context>
<context>
    <name>prisca::app::ChannelMapEditor</name>
    <message>
        <location filename="../app/widgets/ChannelMapEditor.cpp" line="84"/>
        <source>&apos;%1&apos; is not a number</source>
        <translation>「%1」不是數字</translation>
    </message>
    <message>
        <location filename="../app/widgets/ChannelMapEditor.cpp" line="124"/>
        <source>CH</source>
        <translation>通道</translation>
    </message>
    <message>
        <location filename="../app/widgets/ChannelMapEditor.cpp" line="124"/>
        <source>trim [µs]</source>
        <translation>微調 [µs]</translation>
    </message>
    <message>
        <location filename="../app/widgets/ChannelMapEditor.cpp" line="124"/>
        <source>min [µs]</source>
        <translation>最小 [µs]</translation>
    </message>
    <message>
        <location filename="../app/widgets/ChannelMapEditor.cpp" line="124"/>
        <source>max [µs]</source>
        <translation>最大 [µs]</translation>
    </message>
    <message>
        <location filename="../app/widgets/ChannelMapEditor.cpp" line="124"/>
        <source>reversed</source>
        <translation>反向</translation>
    </message>
    <message>
        <location filename="../app/widgets/ChannelMapEditor.cpp" line="126"/>
        <source>Which transmitter channel each control drives, its trim, its travel limits and its direction</source>
        <translation>每個控制驅動哪個發射器通道，及其微調、行程限值和方向</translation>
    </message>
</context>
<context>
    <name>prisca::app::ControllerPanel</name>
    <message>
        <location filename="../app/panels/ControllerPanel.cpp" line="35"/>
        <source>steps</source>
        <translation>步</translation>
    </message>
    <message>
        <location filename="../app/panels/ControllerPanel.cpp" line="38"/>
        <source>samples</source>
        <translation>個樣本</translation>
    </message>
    <message>
        <location filename="../app/panels/ControllerPanel.cpp" line="224"/>
        <source>error in %1</source>
        <translation>%1 的誤差</translation>
    </message>
    <message>
        <location filename="../app/panels/ControllerPanel.cpp" line="225"/>
        <source>state %1</source>
        <translation>狀態 %1</translation>
    </message>
    <message>
        <location filename="../app/panels/ControllerPanel.cpp" line="226"/>
        <source>constant</source>
        <translation>常數</translation>
    </message>
    <message>
        <location filename="../app/panels/ControllerPanel.cpp" line="228"/>
        <source>Scale of φ%1 of %2: %3 (Algorithm 1, line 3)</source>
        <translation>%2 的 φ%1 比例：%3（演算法 1，第 3 行）</translation>
    </message>
    <message>
        <location filename="../app/panels/ControllerPanel.cpp" line="239"/>
        <location filename="../app/panels/ControllerPanel.cpp" line="393"/>
        <source>lower</source>
        <translation>下限</translation>
    </message>
    <message>
        <location filename="../app/panels/ControllerPanel.cpp" line="239"/>
        <location filename="../app/panels/ControllerPanel.cpp" line="393"/>
        <source>upper</source>
        <translation>上限</translation>
    </message>
    <message>
        <location filename="../app/panels/ControllerPanel.cpp" line="245"/>
        <source>The controller saturates %1 to this [%2]</source>
        <translation>控制器把 %1 限制於此 [%2]</translation>
    </message>
    <message>
        <location filename="../app/panels/ControllerPanel.cpp" line="323"/>
        <location filename="../app/panels/ControllerPanel.cpp" line="367"/>
        <source>Controller</source>
        <translation>控制器</translation>
    </message>
    <message>
        <location filename="../app/panels/ControllerPanel.cpp" line="339"/>
        <source>Feature φ%1 of %2 must be a number.</source>
        <translation>%2 的特徵 φ%1 必須是數字。</translation>
    </message>
    <message>
        <location filename="../app/panels/ControllerPanel.cpp" line="355"/>
        <source>Limits of %1 must be numbers with lower &lt; upper, within [%2, %3].</source>
        <translation>%1 的限值必須是數字，下限 &lt; 上限，並在 [%2, %3] 之內。</translation>
    </message>
    <message>
        <location filename="../app/panels/ControllerPanel.cpp" line="402"/>
        <source>Method:</source>
        <translation>方法：</translation>
    </message>
    <message>
        <location filename="../app/panels/ControllerPanel.cpp" line="435"/>
        <source>Restore the plant&apos;s tuned preset</source>
        <translation>還原此對象的調校預設值</translation>
    </message>
    <message>
        <location filename="../app/panels/ControllerPanel.cpp" line="436"/>
        <source>Feature scales φ (per control; the policy is u = u* + θᵀφ):</source>
        <translation>特徵比例 φ（按控制通道；策略為 u = u* + θᵀφ）：</translation>
    </message>
    <message>
        <location filename="../app/panels/ControllerPanel.cpp" line="437"/>
        <source>Action limits:</source>
        <translation>動作限值：</translation>
    </message>
    <message>
        <location filename="../app/panels/ControllerPanel.cpp" line="403"/>
        <source>PRISCA, or a comparison method of Table I (PD family, LQR, action playback, PGSD, PEGASUS, ILC), or the limit: the oracle, which plans on copies of the simulated plant itself (simulation only).</source>
        <translation>PRISCA，或表 I 的比較方法（PD 系列、LQR、動作重播、PGSD、PEGASUS、ILC），或極限：預言者，它在模擬對象本身的副本上規劃（只限模擬）。</translation>
    </message>
</context>
<context>
    <name>prisca::app::EmergencyStop</name>
    <message>
        <location filename="../app/EmergencyStop.cpp" line="10"/>
        <source>E-STOP is latched (pressed at %1 by %2): press Reset E-STOP first.</source>
        <translation>緊急停止已鎖定（%1 由%2觸發）：請先按「重設緊急停止」。</translation>
    </message>
</context>
<context>
    <name>prisca::app::EmergencyStopGuard</name>
    <message>
        <location filename="../app/EmergencyStopGuard.cpp" line="124"/>
        <source>Space</source>
        <translation>空白鍵</translation>
    </message>
    <message>
        <location filename="../app/EmergencyStopGuard.cpp" line="124"/>
        <source>Esc</source>
        <translation>Esc 鍵</translation>
    </message>
    <message>
        <location filename="../app/EmergencyStopGuard.cpp" line="186"/>
        <source>the E-STOP button</source>
        <translation>緊急停止按鈕</translation>
    </message>
</context>
<context>
    <name>prisca::app::ExperimentsPanel</name>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="187"/>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="225"/>
        <source>Experiment</source>
        <translation>實驗</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="226"/>
        <source>Table I compares final positions and headings, so it needs a vehicle: choose the slide-car or the aircraft as the target.</source>
        <translation>表 I 比較最終位置和航向，所以需要車輛或飛機：請選擇漂移車或飛機作為對象。</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="252"/>
        <source>Starting...</source>
        <translation>開始中...</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="265"/>
        <source>Cancelling: the trials under way finish first...</source>
        <translation>取消中：正在進行的試驗會先完成...</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="306"/>
        <source> (cancelled: %1 trials finished)</source>
        <translation>（已取消：完成了 %1 次試驗）</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="311"/>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="365"/>
        <source>Method</source>
        <translation>方法</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="311"/>
        <source>Position [cm]</source>
        <translation>位置 [厘米]</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="311"/>
        <source>Var. [cm²]</source>
        <translation>方差 [厘米²]</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="312"/>
        <source>Orientation [deg]</source>
        <translation>方向 [度]</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="312"/>
        <source>Var. [deg²]</source>
        <translation>方差 [度²]</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="299"/>
        <source>Slide parking in simulation (%1): %2 trials per method, seed %3; demonstration: %4</source>
        <translation>模擬漂移泊車（%1）：每種方法 %2 次試驗，種子 %3；示範：%4</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="197"/>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="218"/>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="252"/>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="264"/>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="415"/>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="428"/>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="445"/>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="569"/>
        <source>Experiments</source>
        <translation>實驗</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="198"/>
        <source>E-STOP: the experiment stops once the trials under way end; what finished is kept and marked partial.</source>
        <translation>緊急停止：進行中的試驗結束後實驗即停止；已完成的部分會保留並標為不完整。</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="311"/>
        <source>N</source>
        <translation>N</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="317"/>
        <source> (partial)</source>
        <translation>（部分）</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="351"/>
        <source>Learning curves (%1): %2 runs per method, %3 steps each, seed %4; demonstration: %5</source>
        <translation>學習曲線（%1）：每種方法 %2 次運行，每次 %3 步，種子 %4；示範：%5</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="359"/>
        <source> (cancelled)</source>
        <translation>（已取消）</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="365"/>
        <source>First point</source>
        <translation>第一點</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="365"/>
        <source>Half way</source>
        <translation>中段</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="365"/>
        <source>Last point reached</source>
        <translation>最後到達的點</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="394"/>
        <source>mean squared position error [m²]</source>
        <translation>均方位置誤差 [米²]</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="395"/>
        <source>mean squared joint-angle error [rad²]</source>
        <translation>均方關節角誤差 [弧度²]</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="416"/>
        <source>The result could not be kept for the next session: %1</source>
        <translation>結果未能保留至下次使用：%1</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="429"/>
        <source>The last session&apos;s experiment could not be shown again: %1</source>
        <translation>上次的實驗未能再次顯示：%1</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="447"/>
        <source>The last experiment, cancelled %1 (its rows are partial), is shown again; Start runs a new one.</source>
        <translation>再次顯示上次於 %1 取消的實驗（各行不完整）；按「開始」執行新實驗。</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="450"/>
        <source>The last experiment, finished %1, is shown again; Start runs a new one.</source>
        <translation>再次顯示上次於 %1 完成的實驗；按「開始」執行新實驗。</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsExport.cpp" line="89"/>
        <source>There is no result to export yet.</source>
        <translation>尚未有可匯出的結果。</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsExport.cpp" line="102"/>
        <source>There is no figure to export yet.</source>
        <translation>尚未有可匯出的圖。</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsExport.cpp" line="111"/>
        <location filename="../app/panels/ExperimentsExport.cpp" line="123"/>
        <source>Export table</source>
        <translation>匯出表格</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsExport.cpp" line="112"/>
        <source>Markdown (*.md);;CSV (*.csv);;LaTeX (*.tex)</source>
        <translation>Markdown (*.md);;CSV (*.csv);;LaTeX (*.tex)</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsExport.cpp" line="128"/>
        <location filename="../app/panels/ExperimentsExport.cpp" line="138"/>
        <source>Export figure</source>
        <translation>匯出圖</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsExport.cpp" line="129"/>
        <source>PNG pictures (*.png);;SVG drawings (*.svg)</source>
        <translation>PNG 圖片 (*.png);;SVG 繪圖 (*.svg)</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="500"/>
        <source>Table I: slide parking, every method</source>
        <translation>表 I：漂移泊車，所有方法</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="501"/>
        <source>Learning curves: PRISCA, PGSD, PEGASUS</source>
        <translation>學習曲線：PRISCA、PGSD、PEGASUS</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="503"/>
        <source>Runs per method:</source>
        <translation>每種方法的運行次數：</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="503"/>
        <source>Trials per method:</source>
        <translation>每種方法的試驗次數：</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="504"/>
        <source>Seed:</source>
        <translation>隨機種子：</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="505"/>
        <source>Budget:</source>
        <translation>預算：</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="506"/>
        <source> steps</source>
        <translation> 步</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="507"/>
        <source>Simulated control steps each run may use (the same for every method)</source>
        <translation>每次運行可用的模擬控制步數（所有方法相同）</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="509"/>
        <source>Start</source>
        <translation>開始</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="510"/>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="511"/>
        <source>Export table...</source>
        <translation>匯出表格...</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="512"/>
        <source>Export figure...</source>
        <translation>匯出圖...</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="513"/>
        <source>Click to open the figure large</source>
        <translation>按一下以大圖打開</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="542"/>
        <source>Starting... %1 so far</source>
        <translation>正在開始……已用 %1</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="544"/>
        <source>Run %1 of %2 done</source>
        <translation>已完成第 %1 次運行（共 %2 次）</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="545"/>
        <source>Trial %1 of %2 done</source>
        <translation>已完成第 %1 次試驗（共 %2 次）</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="549"/>
        <source>E-STOP: stopping once the trials under way end. %1</source>
        <translation>緊急停止：進行中的試驗結束後即停止。%1</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="551"/>
        <source>Cancelling: the trials under way finish first. %1</source>
        <translation>正在取消：先完成進行中的試驗。%1</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="562"/>
        <source>Cancelled: %v of %m runs</source>
        <translation>已取消：完成 %v / %m 次運行</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="563"/>
        <source>Cancelled: %v of %m trials</source>
        <translation>已取消：完成 %v / %m 次試驗</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="571"/>
        <source>Finished in %1.</source>
        <translation>用時 %1 完成。</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="573"/>
        <source>Stopped by E-STOP after %1: the rows are partial.</source>
        <translation>%1 後被緊急停止：各行不完整。</translation>
    </message>
    <message>
        <location filename="../app/panels/ExperimentsPanel.cpp" line="574"/>
        <source>Cancelled after %1: the rows are partial.</source>
        <translation>%1 後已取消：各行不完整。</translation>
    </message>
</context>
<context>
    <name>prisca::app::GamepadEmergencyButton</name>
    <message>
        <location filename="../app/input/GamepadEmergencyButton.cpp" line="55"/>
        <source>gamepad button %1</source>
        <translation>手掣按鈕 %1</translation>
    </message>
</context>
<context>
    <name>prisca::app::LabSession</name>
    <message>
        <location filename="../app/LabSessionFile.cpp" line="51"/>
        <source>&apos;%1&apos; must be a number from %2 to %3</source>
        <translation>「%1」必須是 %2 至 %3 之間的數字</translation>
    </message>
    <message>
        <location filename="../app/LabSessionFile.cpp" line="65"/>
        <source>&apos;%1&apos; must be a whole number</source>
        <translation>「%1」必須是整數</translation>
    </message>
    <message>
        <location filename="../app/LabSessionFile.cpp" line="93"/>
        <source>&apos;%1&apos; must have %2 lists of scales</source>
        <translation>「%1」必須有 %2 組比例</translation>
    </message>
    <message>
        <location filename="../app/LabSessionFile.cpp" line="99"/>
        <source>&apos;%1&apos; list %2 must have %3 scales</source>
        <translation>「%1」第 %2 組必須有 %3 個比例</translation>
    </message>
    <message>
        <location filename="../app/LabSessionFile.cpp" line="107"/>
        <source>&apos;%1&apos; list %2 entry %3 must be a number</source>
        <translation>「%1」第 %2 組第 %3 項必須是數字</translation>
    </message>
    <message>
        <location filename="../app/LabSession.cpp" line="30"/>
        <source>the plant file %1 describes a %2, not a %3</source>
        <translation>機型檔 %1 描述的是 %2，不是 %3</translation>
    </message>
    <message>
        <location filename="../app/LabSession.cpp" line="49"/>
        <source>the plant&apos;s physical parameters changed</source>
        <translation>對象的物理參數已改變</translation>
    </message>
    <message>
        <location filename="../app/LabSession.cpp" line="67"/>
        <source>the target changed</source>
        <translation>目標已改變</translation>
    </message>
    <message>
        <location filename="../app/LabSession.cpp" line="74"/>
        <source>no demonstration</source>
        <translation>沒有示範</translation>
    </message>
    <message>
        <location filename="../app/LabSession.cpp" line="82"/>
        <source>the demonstration does not fit the %1: %2</source>
        <translation>示範不適用於 %1：%2</translation>
    </message>
    <message>
        <location filename="../app/LabSession.cpp" line="90"/>
        <location filename="../app/LabSession.cpp" line="120"/>
        <source>the demonstration changed</source>
        <translation>示範已改變</translation>
    </message>
    <message>
        <location filename="../app/LabSession.cpp" line="97"/>
        <source>the scripted operator (%1, seed %2)</source>
        <translation>腳本操作員（%1，種子 %2）</translation>
    </message>
    <message>
        <location filename="../app/LabSession.cpp" line="109"/>
        <source>the %1 has no demonstration style &apos;%2&apos;</source>
        <translation>%1 沒有示範風格「%2」</translation>
    </message>
    <message>
        <location filename="../app/LabSession.cpp" line="148"/>
        <source>an identification that was refused or cancelled is no model</source>
        <translation>被拒絕或已取消的辨識不是模型</translation>
    </message>
    <message>
        <location filename="../app/LabSession.cpp" line="153"/>
        <source>the model is of a %1, the target a %2</source>
        <translation>模型屬於 %1，目標卻是 %2</translation>
    </message>
    <message>
        <location filename="../app/LabSession.cpp" line="159"/>
        <source>the demonstration changed while the model was identified</source>
        <translation>辨識模型期間示範已改變</translation>
    </message>
    <message>
        <location filename="../app/LabSessionFile.cpp" line="211"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location filename="../app/LabSessionFile.cpp" line="217"/>
        <source>not valid JSON at byte %1 (%2)</source>
        <translation>第 %1 個位元組處不是有效的 JSON（%2）</translation>
    </message>
    <message>
        <location filename="../app/LabSessionFile.cpp" line="223"/>
        <source>not a PRISCA Lab session (no &quot;format&quot;: &quot;prisca-session&quot;)</source>
        <translation>不是 PRISCA Lab 工作階段檔（沒有 &quot;format&quot;: &quot;prisca-session&quot;）</translation>
    </message>
    <message>
        <location filename="../app/LabSessionFile.cpp" line="226"/>
        <source>written by a newer PRISCA Lab (session version %1)</source>
        <translation>由較新版本的 PRISCA Lab 寫入（工作階段版本 %1）</translation>
    </message>
    <message>
        <location filename="../app/LabSessionFile.cpp" line="231"/>
        <source>&apos;plant&apos; must be one of %1</source>
        <translation>「plant」必須是以下其中之一：%1</translation>
    </message>
    <message>
        <location filename="../app/LabSessionFile.cpp" line="238"/>
        <source>&apos;mapping&apos;: %1</source>
        <translation>「mapping」：%1</translation>
    </message>
    <message>
        <location filename="../app/LabSessionFile.cpp" line="242"/>
        <source>&apos;mapping&apos; must have %1 rows of %2 signs for the %3</source>
        <translation>%3 的「mapping」必須有 %1 行、每行 %2 個符號</translation>
    </message>
    <message>
        <location filename="../app/LabSessionFile.cpp" line="251"/>
        <source>&apos;method&apos; must be one of %1</source>
        <translation>「method」必須是以下其中之一：%1</translation>
    </message>
    <message>
        <location filename="../app/LabSessionFile.cpp" line="273"/>
        <source>&apos;%1&apos;: %2</source>
        <translation>「%1」：%2</translation>
    </message>
    <message>
        <location filename="../app/LabSessionFile.cpp" line="340"/>
        <source>&apos;parameters&apos; must be an object of &quot;name&quot;: &quot;value&quot;</source>
        <translation>「parameters」必須是 &quot;名稱&quot;: &quot;值&quot; 的物件</translation>
    </message>
    <message>
        <location filename="../app/LabSessionFile.cpp" line="346"/>
        <source>&apos;parameters.%1&apos; must be a string such as &quot;10&quot; or &quot;1,1.2&quot;</source>
        <translation>「parameters.%1」必須是如 &quot;10&quot; 或 &quot;1,1.2&quot; 的字串</translation>
    </message>
    <message>
        <location filename="../app/LabSessionFile.cpp" line="367"/>
        <source>&apos;limits.%1&apos; must be a list of %2 numbers</source>
        <translation>「limits.%1」必須是含 %2 個數字的列表</translation>
    </message>
    <message>
        <location filename="../app/LabSessionFile.cpp" line="381"/>
        <source>&apos;limits&apos; of %1 must have lower &lt; upper within [%2, %3]</source>
        <translation>%1 的「limits」必須下限 &lt; 上限，並在 [%2, %3] 之內</translation>
    </message>
    <message>
        <location filename="../app/LabSessionFile.cpp" line="407"/>
        <source>&apos;plantParameters&apos;: %1</source>
        <translation>「plantParameters」：%1</translation>
    </message>
    <message>
        <location filename="../app/LabSessionFile.cpp" line="421"/>
        <source>its demonstration: %1</source>
        <translation>其示範：%1</translation>
    </message>
    <message>
        <location filename="../app/LabSessionFile.cpp" line="425"/>
        <source>its demonstration %1 is not a %2 demonstration</source>
        <translation>其示範 %1 不是 %2 的示範</translation>
    </message>
    <message>
        <location filename="../app/LabSessionFile.cpp" line="432"/>
        <source>&apos;scriptedStyle&apos; must be one of %1</source>
        <translation>「scriptedStyle」必須是 %1 之一</translation>
    </message>
    <message>
        <location filename="../app/LabSessionFile.cpp" line="437"/>
        <source>&apos;scriptedSeed&apos; must be a whole number from 0 to 9e15</source>
        <translation>「scriptedSeed」必須是 0 至 9e15 的整數</translation>
    </message>
    <message>
        <location filename="../app/LabSessionFile.cpp" line="465"/>
        <source>The identified model saved with it could not be read (%1): identify the car again in the Model step.</source>
        <translation>無法讀取隨工作階段儲存的已辨識模型（%1）：請在「模型」步驟重新辨識車輛。</translation>
    </message>
    <message>
        <location filename="../app/LabSessionFile.cpp" line="470"/>
        <source>Its demonstration is not the one the saved model was identified from: identify the car again in the Model step.</source>
        <translation>其示範並非儲存的模型辨識時所用的示範：請在「模型」步驟重新辨識車輛。</translation>
    </message>
    <message>
        <location filename="../app/LabSessionFile.cpp" line="487"/>
        <source>Saved by an earlier PRISCA Lab: its PRISCA, PD and ILC parameters were tuned for an earlier PRISCA, so today&apos;s defaults are used instead.</source>
        <translation>由較早版本的 PRISCA Lab 儲存：其 PRISCA、PD 及 ILC 參數是為較早的 PRISCA 調校的，因此改用今日的預設值。</translation>
    </message>
</context>
<context>
    <name>prisca::app::LanguageMenu</name>
    <message>
        <location filename="../app/LanguageMenu.cpp" line="40"/>
        <source>&amp;Language</source>
        <translation>語言(&amp;L)</translation>
    </message>
</context>
<context>
    <name>prisca::app::LiveChartsPanel</name>
    <message>
        <location filename="../app/panels/LiveChartsPanel.cpp" line="384"/>
        <source>Trial %1, run time %2 s</source>
        <translation>試驗 %1，運行時間 %2 s</translation>
    </message>
    <message>
        <location filename="../app/panels/LiveChartsPanel.cpp" line="387"/>
        <source>error %1 %2, smoothed %3 %2</source>
        <translation>誤差 %1 %2，平滑後 %3 %2</translation>
    </message>
    <message>
        <location filename="../app/panels/LiveChartsPanel.cpp" line="402"/>
        <source>%1: u %2, u* %3 %4</source>
        <translation>%1：u %2，u* %3 %4</translation>
    </message>
    <message>
        <location filename="../app/panels/LiveChartsExport.cpp" line="141"/>
        <source>cannot encode the picture for %1</source>
        <translation>無法為 %1 編碼圖片</translation>
    </message>
    <message>
        <location filename="../app/panels/LiveChartsExport.cpp" line="163"/>
        <location filename="../app/panels/LiveChartsExport.cpp" line="168"/>
        <source>Export chart data</source>
        <translation>匯出圖表數據</translation>
    </message>
    <message>
        <location filename="../app/panels/LiveChartsExport.cpp" line="164"/>
        <source>CSV files (*.csv)</source>
        <translation>CSV 檔案 (*.csv)</translation>
    </message>
    <message>
        <location filename="../app/panels/LiveChartsExport.cpp" line="174"/>
        <location filename="../app/panels/LiveChartsExport.cpp" line="179"/>
        <source>Export charts as picture</source>
        <translation>把圖表匯出為圖片</translation>
    </message>
    <message>
        <location filename="../app/panels/LiveChartsExport.cpp" line="175"/>
        <source>PNG pictures (*.png)</source>
        <translation>PNG 圖片 (*.png)</translation>
    </message>
    <message>
        <location filename="../app/panels/LiveChartsPanel.cpp" line="444"/>
        <source>Tracking error</source>
        <translation>追蹤誤差</translation>
    </message>
    <message>
        <location filename="../app/panels/LiveChartsPanel.cpp" line="445"/>
        <source>Policy θ</source>
        <translation>策略 θ</translation>
    </message>
    <message>
        <location filename="../app/panels/LiveChartsPanel.cpp" line="446"/>
        <source>Action u and u*</source>
        <translation>動作 u 與 u*</translation>
    </message>
    <message>
        <location filename="../app/panels/LiveChartsPanel.cpp" line="447"/>
        <source>error</source>
        <translation>誤差</translation>
    </message>
    <message>
        <location filename="../app/panels/LiveChartsPanel.cpp" line="448"/>
        <source>smoothed (1 s)</source>
        <translation>平滑（1 秒）</translation>
    </message>
    <message>
        <location filename="../app/panels/LiveChartsPanel.cpp" line="451"/>
        <source>error [m]</source>
        <translation>誤差 [米]</translation>
    </message>
    <message>
        <location filename="../app/panels/LiveChartsPanel.cpp" line="451"/>
        <source>error [rad]</source>
        <translation>誤差 [弧度]</translation>
    </message>
    <message>
        <location filename="../app/panels/LiveChartsPanel.cpp" line="453"/>
        <source>run time [s]</source>
        <translation>運行時間 [秒]</translation>
    </message>
    <message>
        <location filename="../app/panels/LiveChartsPanel.cpp" line="455"/>
        <source>θ</source>
        <translation>θ</translation>
    </message>
    <message>
        <location filename="../app/panels/LiveChartsPanel.cpp" line="456"/>
        <source>action</source>
        <translation>動作</translation>
    </message>
    <message>
        <location filename="../app/panels/LiveChartsPanel.cpp" line="457"/>
        <source>Freeze</source>
        <translation>凍結</translation>
    </message>
    <message>
        <location filename="../app/panels/LiveChartsPanel.cpp" line="458"/>
        <source>Stop redrawing to look closely; the data keeps being recorded.</source>
        <translation>暫停重繪以便細看；數據仍會繼續記錄。</translation>
    </message>
    <message>
        <location filename="../app/panels/LiveChartsPanel.cpp" line="459"/>
        <source>Fit</source>
        <translation>全部顯示</translation>
    </message>
    <message>
        <location filename="../app/panels/LiveChartsPanel.cpp" line="460"/>
        <source>Show all the data again after zooming (drag a box to zoom).</source>
        <translation>縮放後重新顯示全部數據（拖出方框即可縮放）。</translation>
    </message>
    <message>
        <location filename="../app/panels/LiveChartsPanel.cpp" line="461"/>
        <source>Export CSV...</source>
        <translation>匯出 CSV...</translation>
    </message>
    <message>
        <location filename="../app/panels/LiveChartsPanel.cpp" line="462"/>
        <source>Export PNG...</source>
        <translation>匯出 PNG...</translation>
    </message>
</context>
<context>
    <name>prisca::app::MainWindow</name>
    <message>
        <location filename="../app/MainWindow.cpp" line="123"/>
        <source>the last session</source>
        <translation>上次的工作階段</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="150"/>
        <location filename="../app/MainWindow.cpp" line="469"/>
        <location filename="../app/MainWindow.cpp" line="476"/>
        <source>Run</source>
        <translation>運行</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="153"/>
        <location filename="../app/MainWindow.cpp" line="390"/>
        <location filename="../app/MainWindow.cpp" line="398"/>
        <location filename="../app/MainWindow.cpp" line="400"/>
        <location filename="../app/MainWindow.cpp" line="414"/>
        <source>Session</source>
        <translation>工作階段</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="349"/>
        <source>%1 on the %2; demonstration: %3</source>
        <translation>%1，對象：%2；示範：%3</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="107"/>
        <source>the E-STOP button</source>
        <translation>緊急停止按鈕</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="111"/>
        <location filename="../app/MainWindowMenus.cpp" line="234"/>
        <location filename="../app/MainWindowMenus.cpp" line="238"/>
        <source>E-STOP LATCHED</source>
        <translation>緊急停止已鎖定</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="173"/>
        <source>The quit was called off; the work goes on.</source>
        <translation>已取消結束；工作繼續。</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="180"/>
        <source>Quits when the work under way is done</source>
        <translation>進行中的工作完成後結束</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="181"/>
        <source>Quits once the work has stopped</source>
        <translation>工作停止後即結束</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="182"/>
        <source>Don&apos;t quit</source>
        <translation>不要結束</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="193"/>
        <source>Job: simulated run</source>
        <translation>工作：模擬運行</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="196"/>
        <source>Job: simulated run, PAUSED</source>
        <translation>工作：模擬運行，已暫停</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="203"/>
        <source>Job: experiment, %1 of %2</source>
        <translation>工作：實驗，%1 / %2</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="206"/>
        <source>Job: experiment, starting</source>
        <translation>工作：實驗，啟動中</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="209"/>
        <source>Job: rig trial</source>
        <translation>工作：實驗台試驗</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="218"/>
        <source>Job: measuring latency</source>
        <translation>工作：量度延遲</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="221"/>
        <source>Job: recording</source>
        <translation>工作：錄製中</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="224"/>
        <source>Job: none</source>
        <translation>工作：無</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="234"/>
        <source>E-STOP ready</source>
        <translation>緊急停止就緒</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="382"/>
        <location filename="../app/MainWindowMenus.cpp" line="266"/>
        <source>Open session</source>
        <translation>開啟工作階段</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="267"/>
        <source>PRISCA Lab sessions (*.json);;All files (*)</source>
        <translation>PRISCA Lab 工作階段 (*.json);;所有檔案 (*)</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="409"/>
        <location filename="../app/MainWindowMenus.cpp" line="278"/>
        <source>Save session</source>
        <translation>儲存工作階段</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="279"/>
        <source>PRISCA Lab sessions (*.json)</source>
        <translation>PRISCA Lab 工作階段 (*.json)</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="485"/>
        <source>Replay a trial bundle</source>
        <translation>重播試驗包</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="325"/>
        <source>E-STOP reset</source>
        <translation>緊急停止已重設</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="190"/>
        <source>Job: preparing the run (training, or identifying the model)</source>
        <translation>工作：準備運行（訓練，或識別模型）</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="213"/>
        <source>Job: identifying the model, %1 %</source>
        <translation>工作：正在辨識模型，%1 %</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="215"/>
        <source>Job: identifying the model</source>
        <translation>工作：正在辨識模型</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="325"/>
        <location filename="../app/MainWindowMenus.cpp" line="405"/>
        <location filename="../app/MainWindowMenus.cpp" line="502"/>
        <location filename="../app/MainWindowMenus.cpp" line="515"/>
        <location filename="../app/MainWindowMenus.cpp" line="590"/>
        <source>E-STOP</source>
        <translation>緊急停止</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="383"/>
        <source>The session could not be opened.

%1</source>
        <translation>無法開啟工作階段。

%1</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="391"/>
        <source>The messages saved with %1 follow (%2 lines).</source>
        <translation>以下是與 %1 一同儲存的訊息（%2 行）。</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="398"/>
        <source>Opened %1</source>
        <translation>已開啟 %1</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="400"/>
        <source>Opened %1. %2</source>
        <translation>已開啟 %1。%2</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="414"/>
        <source>Saved %1</source>
        <translation>已儲存 %1</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="455"/>
        <source>&amp;File</source>
        <translation>檔案(&amp;F)</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="456"/>
        <source>&amp;Open session...</source>
        <translation>開啟工作階段(&amp;O)...</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="457"/>
        <source>Open &amp;recent</source>
        <translation>最近開啟(&amp;R)</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="458"/>
        <source>&amp;Save session as...</source>
        <translation>工作階段另存為(&amp;S)...</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="459"/>
        <source>&amp;Quit</source>
        <translation>結束(&amp;Q)</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="460"/>
        <source>&amp;Replay a trial bundle...</source>
        <translation>重播試驗包(&amp;R)...</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="461"/>
        <source>E-STOP &amp;inputs...</source>
        <translation>緊急停止輸入(&amp;I)……</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="463"/>
        <source>A foot switch&apos;s key and a gamepad button that are E-STOP too</source>
        <translation>同樣觸發緊急停止的腳踏開關按鍵和手掣按鈕</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="467"/>
        <source>Close the window and leave PRISCA Lab</source>
        <translation>關閉視窗並離開 PRISCA Lab</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="468"/>
        <source>&amp;Run</source>
        <translation>運行(&amp;R)</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="470"/>
        <source>&amp;View</source>
        <translation>檢視(&amp;V)</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="471"/>
        <source>Task</source>
        <translation>任務</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="472"/>
        <source>Record</source>
        <translation>錄製</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="473"/>
        <source>Mapping</source>
        <translation>映射</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="474"/>
        <source>Model</source>
        <translation>模型</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="475"/>
        <source>Controller</source>
        <translation>控制器</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="477"/>
        <source>Live charts</source>
        <translation>即時圖表</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="478"/>
        <source>Experiments</source>
        <translation>實驗</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="479"/>
        <source>Rig</source>
        <translation>實機</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="480"/>
        <source>Messages</source>
        <translation>訊息</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="481"/>
        <source>&amp;Help</source>
        <translation>說明(&amp;H)</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="482"/>
        <source>&amp;About PRISCA Lab</source>
        <translation>關於 PRISCA Lab(&amp;A)</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="483"/>
        <source>Operator &amp;guide</source>
        <translation>操作指南(&amp;G)</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="484"/>
        <source>&amp;Keyboard shortcuts</source>
        <translation>鍵盤快捷鍵(&amp;K)</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="485"/>
        <source>Show the version and what PRISCA Lab does</source>
        <translation>顯示版本及 PRISCA Lab 的用途</translation>
    </message>
    <message>
        <location filename="../app/MainWindow.cpp" line="487"/>
        <source>Version %1</source>
        <translation>版本 %1</translation>
    </message>
    <message>
        <location filename="../app/MainWindowQuit.cpp" line="78"/>
        <source>a simulated run</source>
        <translation>一次模擬運行</translation>
    </message>
    <message>
        <location filename="../app/MainWindowQuit.cpp" line="81"/>
        <source>an experiment (%1 of %2 done)</source>
        <translation>一個實驗（已完成 %1 / %2）</translation>
    </message>
    <message>
        <location filename="../app/MainWindowQuit.cpp" line="86"/>
        <source>a trial on the rig</source>
        <translation>一次實驗台試驗</translation>
    </message>
    <message>
        <location filename="../app/MainWindowQuit.cpp" line="89"/>
        <source>a latency measurement on the rig</source>
        <translation>一次實驗台延遲量度</translation>
    </message>
    <message>
        <location filename="../app/MainWindowQuit.cpp" line="92"/>
        <source>a recording</source>
        <translation>一次錄製</translation>
    </message>
    <message>
        <location filename="../app/MainWindowQuit.cpp" line="95"/>
        <source>an identification of the car&apos;s model</source>
        <translation>車輛模型的辨識</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="397"/>
        <source>E-STOP, in every window while something runs (a dialog, a menu, the guide and the replay too; Shift+Space types a space then). With nothing running, in the main window: Space types a space in a text field, Esc first closes an open list</source>
        <translation>有工作進行時，在每個視窗（包括對話框、選單、指南和重播）都是緊急停止；此時按 Shift+空白鍵輸入空格。沒有工作進行時，在主視窗內：空白鍵在文字欄輸入空格，Esc 先關閉已打開的清單</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="402"/>
        <source>E-STOP (the foot switch&apos;s key)</source>
        <translation>緊急停止（腳踏開關的按鍵）</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="405"/>
        <source>Gamepad button %1</source>
        <translation>手掣按鈕 %1</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="503"/>
        <source>The E-STOP key &quot;%1&quot; in the settings is no key; it is left out.</source>
        <translation>設定中的緊急停止按鍵「%1」不是按鍵，已略去。</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="516"/>
        <source>The gamepad button &quot;%1&quot; in the settings is no button SDL knows; it is left out.</source>
        <translation>設定中的手掣按鈕「%1」不是 SDL 認識的按鈕，已略去。</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="527"/>
        <source>E-STOP inputs</source>
        <translation>緊急停止輸入</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="529"/>
        <source>Space, Esc and the red button are always E-STOP. A USB foot switch can be set to send a key (F13, Pause, ...): press that key here. A gamepad&apos;s button is E-STOP too, whatever the window shows.</source>
        <translation>空白鍵、Esc 和紅色按鈕永遠是緊急停止。USB 腳踏開關可設定為發出某個按鍵（F13、Pause 等）：在這裏按下該按鍵。手掣的按鈕也可作緊急停止，不論視窗顯示甚麼。</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="539"/>
        <source>No key</source>
        <translation>不設按鍵</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="546"/>
        <source>None</source>
        <translation>無</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="548"/>
        <source>B (the red one on most pads)</source>
        <translation>B（大多數手掣上的紅色按鈕）</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="549"/>
        <source>A</source>
        <translation>A</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="550"/>
        <source>X</source>
        <translation>X</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="551"/>
        <source>Y</source>
        <translation>Y</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="552"/>
        <source>Back / Select</source>
        <translation>Back / Select</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="553"/>
        <source>Start</source>
        <translation>Start</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="554"/>
        <source>Left shoulder</source>
        <translation>左肩鍵</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="555"/>
        <source>Right shoulder</source>
        <translation>右肩鍵</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="556"/>
        <source>Paddle 1</source>
        <translation>背鍵 1</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="562"/>
        <source>A gamepad is connected.</source>
        <translation>已連接手掣。</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="563"/>
        <source>No gamepad is connected now.</source>
        <translation>目前沒有連接手掣。</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="566"/>
        <source>Foot switch key:</source>
        <translation>腳踏開關按鍵：</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="567"/>
        <source>Gamepad button:</source>
        <translation>手掣按鈕：</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="591"/>
        <source>E-STOP inputs: Space, Esc, the red button%1%2</source>
        <translation>緊急停止輸入：空白鍵、Esc、紅色按鈕%1%2</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="594"/>
        <source>, the key %1</source>
        <translation>、按鍵 %1</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="595"/>
        <source>, gamepad button %1</source>
        <translation>、手掣按鈕 %1</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="173"/>
        <location filename="../app/MainWindowQuit.cpp" line="118"/>
        <location filename="../app/MainWindowQuit.cpp" line="141"/>
        <location filename="../app/MainWindowQuit.cpp" line="144"/>
        <location filename="../app/MainWindowQuit.cpp" line="151"/>
        <location filename="../app/MainWindowQuit.cpp" line="154"/>
        <location filename="../app/MainWindowQuit.cpp" line="187"/>
        <source>Quit</source>
        <translation>結束</translation>
    </message>
    <message>
        <location filename="../app/MainWindowQuit.cpp" line="119"/>
        <source>Quitting: the work under way is stopped and what is done kept.</source>
        <translation>結束中：進行中的工作已停止，已完成的部分已保留。</translation>
    </message>
    <message>
        <location filename="../app/MainWindowQuit.cpp" line="120"/>
        <source>Quitting: the work under way is discarded.</source>
        <translation>結束中：進行中的工作已捨棄。</translation>
    </message>
    <message>
        <location filename="../app/MainWindowQuit.cpp" line="142"/>
        <source>The run&apos;s log was kept in %1</source>
        <translation>運行記錄已保存於 %1</translation>
    </message>
    <message>
        <location filename="../app/MainWindowQuit.cpp" line="152"/>
        <source>The experiment&apos;s table was kept in %1</source>
        <translation>實驗表格已保存於 %1</translation>
    </message>
    <message>
        <location filename="../app/MainWindowQuit.cpp" line="165"/>
        <source>Quit PRISCA Lab</source>
        <translation>結束 PRISCA Lab</translation>
    </message>
    <message>
        <location filename="../app/MainWindowQuit.cpp" line="166"/>
        <source>Work is under way:

%1

What should happen to it?</source>
        <translation>有工作正在進行：

%1

要如何處理？</translation>
    </message>
    <message>
        <location filename="../app/MainWindowQuit.cpp" line="171"/>
        <source>Finish: quit once it is done. Keep: stop now, save what is done (the run&apos;s log, the experiment&apos;s table, the recording) and quit. Discard: stop now and quit.</source>
        <translation>完成：待其完成後結束。保留：立即停止，儲存已完成的部分（運行記錄、實驗表格、錄製）後結束。捨棄：立即停止並結束。</translation>
    </message>
    <message>
        <location filename="../app/MainWindowQuit.cpp" line="173"/>
        <source>Finish, then quit</source>
        <translation>完成後結束</translation>
    </message>
    <message>
        <location filename="../app/MainWindowQuit.cpp" line="174"/>
        <source>Keep what is done, quit</source>
        <translation>保留已完成的部分並結束</translation>
    </message>
    <message>
        <location filename="../app/MainWindowQuit.cpp" line="175"/>
        <source>Discard, quit</source>
        <translation>捨棄並結束</translation>
    </message>
    <message>
        <location filename="../app/MainWindowQuit.cpp" line="187"/>
        <source>PRISCA Lab quits once the work under way is done.</source>
        <translation>進行中的工作完成後，PRISCA Lab 便會結束。</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="358"/>
        <source>Interface language: %1</source>
        <translation>介面語言：%1</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="358"/>
        <source>Language</source>
        <translation>語言</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="370"/>
        <source>Teaches a robot to repeat one demonstrated manoeuvre precisely.</source>
        <translation>教機械人精準地重複一次示範過的動作。</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="372"/>
        <source>PRISCA (Policy Reasoning In State-and-Cost Adaptation) learns online from a single demonstration and a coarse sign model of the dynamics, such as &quot;steer left to turn left&quot;.</source>
        <translation>PRISCA（Policy Reasoning In State-and-Cost Adaptation）只需一次示範，加上一個粗略的動態正負號模型（例如「方向盤向左扭，車便向左轉」），便能在線學習。</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="376"/>
        <source>Built with Qt %1, running on Qt %2.</source>
        <translation>以 Qt %1 建置，現於 Qt %2 上執行。</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="379"/>
        <source>About PRISCA Lab</source>
        <translation>關於 PRISCA Lab</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="396"/>
        <source>Space or Esc</source>
        <translation>空白鍵或 Esc</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="411"/>
        <source>Arrow keys or W A S D</source>
        <translation>方向鍵或 W A S D</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="412"/>
        <source>Drive while recording: throttle up/down, steer left/right</source>
        <translation>錄製時駕駛：油門加／減，轉向左／右</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="414"/>
        <source>Copy the selected lines of the message log</source>
        <translation>複製訊息記錄中選取的行</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="421"/>
        <source>Keyboard shortcuts</source>
        <translation>鍵盤快捷鍵</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="457"/>
        <location filename="../app/MainWindowMenus.cpp" line="464"/>
        <source>Operator guide</source>
        <translation>操作指南</translation>
    </message>
    <message>
        <location filename="../app/MainWindowMenus.cpp" line="458"/>
        <source>The operator guide is not built into this copy.</source>
        <translation>此版本未內置操作指南。</translation>
    </message>
</context>
<context>
    <name>prisca::app::MappingPanel</name>
    <message>
        <location filename="../app/panels/MappingPanel.cpp" line="142"/>
        <source>Which way %1 moves %2: +1 increases it, −1 decreases it, 0 not at all (B~, eq. 6). Click to change.</source>
        <translation>%1 令 %2 往哪個方向變：+1 增加，−1 減少，0 無影響（B~，式 6）。點擊可更改。</translation>
    </message>
    <message>
        <location filename="../app/panels/MappingPanel.cpp" line="202"/>
        <source>R²</source>
        <translation>R²</translation>
    </message>
    <message>
        <location filename="../app/panels/MappingPanel.cpp" line="202"/>
        <source>set aside</source>
        <translation>剔除</translation>
    </message>
    <message>
        <location filename="../app/panels/MappingPanel.cpp" line="202"/>
        <source>RMS</source>
        <translation>均方根</translation>
    </message>
    <message>
        <location filename="../app/panels/MappingPanel.cpp" line="214"/>
        <source>B[%1, %2] = B_v (.) B~ [%3 per unit of %1, per s]</source>
        <translation>B[%1, %2] = B_v (.) B~ [每單位 %1、每秒的 %3]</translation>
    </message>
    <message>
        <location filename="../app/panels/MappingPanel.cpp" line="221"/>
        <source>Share of the change of %1 the fit explains</source>
        <translation>擬合能解釋的 %1 變化比例</translation>
    </message>
    <message>
        <location filename="../app/panels/MappingPanel.cpp" line="223"/>
        <source>RMS of what the fit leaves unexplained [%1]</source>
        <translation>擬合未能解釋部分的 RMS [%1]</translation>
    </message>
    <message>
        <location filename="../app/panels/MappingPanel.cpp" line="228"/>
        <source>Samples the robust fit set aside (a car sliding, for example)</source>
        <translation>穩健擬合剔除的樣本（例如車輛打滑時）</translation>
    </message>
    <message>
        <location filename="../app/panels/MappingPanel.cpp" line="231"/>
        <source>Fit on %1 samples:</source>
        <translation>以 %1 個樣本擬合：</translation>
    </message>
    <message>
        <location filename="../app/panels/MappingPanel.cpp" line="233"/>
        <source>Residual RMS: what the fit leaves unexplained, per state</source>
        <translation>殘差均方根：擬合未能解釋的部分，按狀態計</translation>
    </message>
    <message>
        <location filename="../app/panels/MappingPanel.cpp" line="246"/>
        <source>Mapping</source>
        <translation>映射</translation>
    </message>
    <message>
        <location filename="../app/panels/MappingPanel.cpp" line="257"/>
        <source>R² below zero for %1: the fit predicts the change of that state worse than its average does. Check those columns&apos; signs in B~ and the latency; a state the controls barely move can also give it.</source>
        <translation>%1 的 R² 低於零：擬合對該狀態變化的預測比其平均值更差。請檢查 B~ 中這些欄的符號及延遲；控制幾乎不影響的狀態也會出現此情況。</translation>
    </message>
    <message>
        <location filename="../app/panels/MappingPanel.cpp" line="282"/>
        <source>Intuitive mapping B~ (which way each control moves each state):</source>
        <translation>直觀映射 B~（每個控制令每個狀態往哪個方向變）：</translation>
    </message>
    <message>
        <location filename="../app/panels/MappingPanel.cpp" line="283"/>
        <source>Latency:</source>
        <translation>延遲：</translation>
    </message>
    <message>
        <location filename="../app/panels/MappingPanel.cpp" line="284"/>
        <location filename="../app/panels/MappingPanel.cpp" line="289"/>
        <source> steps</source>
        <translation> 步</translation>
    </message>
    <message>
        <location filename="../app/panels/MappingPanel.cpp" line="286"/>
        <source>Pairs the state change d steps later with each change of action (eq. 8).</source>
        <translation>把每次動作變化與 d 步之後的狀態變化配對（式 8）。</translation>
    </message>
    <message>
        <location filename="../app/panels/MappingPanel.cpp" line="288"/>
        <source>Response horizon:</source>
        <translation>響應時域：</translation>
    </message>
    <message>
        <location filename="../app/panels/MappingPanel.cpp" line="291"/>
        <source>How many steps of response the fit looks at: 1 is eq. 5&apos;s one-step model; more sees effects that build up (yaw rate into heading).</source>
        <translation>擬合考慮多少步的響應：1 即式 5 的單步模型；更多步可看到逐漸累積的效果（偏航率變成航向）。</translation>
    </message>
    <message>
        <location filename="../app/panels/MappingPanel.cpp" line="293"/>
        <source>Keep the signs of B~ (B_v ≥ 0)</source>
        <translation>保持 B~ 的符號（B_v ≥ 0）</translation>
    </message>
    <message>
        <location filename="../app/panels/MappingPanel.cpp" line="294"/>
        <source>An entry the data would make negative is reported and set to 0.</source>
        <translation>數據會令其變負的項目會被報告並設為 0。</translation>
    </message>
    <message>
        <location filename="../app/panels/MappingPanel.cpp" line="295"/>
        <source>Robust fit</source>
        <translation>穩健擬合</translation>
    </message>
    <message>
        <location filename="../app/panels/MappingPanel.cpp" line="297"/>
        <source>Set aside samples the linear model cannot explain (reweighted least squares).</source>
        <translation>剔除線性模型無法解釋的樣本（重加權最小二乘法）。</translation>
    </message>
    <message>
        <location filename="../app/panels/MappingPanel.cpp" line="299"/>
        <source>Fit B_v</source>
        <translation>擬合 B_v</translation>
    </message>
    <message>
        <location filename="../app/panels/MappingPanel.cpp" line="300"/>
        <source>Fit B_v to the demonstration with this B~ (eq. 8)</source>
        <translation>用此 B~ 把 B_v 擬合到示範（式 8）</translation>
    </message>
</context>
<context>
    <name>prisca::app::MessageLog</name>
    <message>
        <location filename="../app/MessageLog.cpp" line="104"/>
        <source>info</source>
        <translation>資訊</translation>
    </message>
    <message>
        <location filename="../app/MessageLog.cpp" line="106"/>
        <source>warning</source>
        <translation>警告</translation>
    </message>
    <message>
        <location filename="../app/MessageLog.cpp" line="108"/>
        <source>error</source>
        <translation>錯誤</translation>
    </message>
</context>
<context>
    <name>prisca::app::MessageLogPanel</name>
    <message>
        <location filename="../app/panels/MessageLogPanel.cpp" line="173"/>
        <source>All messages</source>
        <translation>所有訊息</translation>
    </message>
    <message>
        <location filename="../app/panels/MessageLogPanel.cpp" line="174"/>
        <source>Warnings and errors</source>
        <translation>警告與錯誤</translation>
    </message>
    <message>
        <location filename="../app/panels/MessageLogPanel.cpp" line="176"/>
        <source>Copy</source>
        <translation>複製</translation>
    </message>
    <message>
        <location filename="../app/panels/MessageLogPanel.cpp" line="177"/>
        <source>Copy the selected lines, or all shown, as tab-separated text (Ctrl+C)</source>
        <translation>以定位字元分隔的文字複製選取的行，或全部顯示的行 (Ctrl+C)</translation>
    </message>
    <message>
        <location filename="../app/panels/MessageLogPanel.cpp" line="178"/>
        <source>Clear</source>
        <translation>清除</translation>
    </message>
    <message>
        <location filename="../app/panels/MessageLogPanel.cpp" line="179"/>
        <source>Time</source>
        <translation>時間</translation>
    </message>
    <message>
        <location filename="../app/panels/MessageLogPanel.cpp" line="179"/>
        <source>Level</source>
        <translation>級別</translation>
    </message>
    <message>
        <location filename="../app/panels/MessageLogPanel.cpp" line="179"/>
        <source>Source</source>
        <translation>來源</translation>
    </message>
    <message>
        <location filename="../app/panels/MessageLogPanel.cpp" line="179"/>
        <source>Message</source>
        <translation>訊息</translation>
    </message>
</context>
<context>
    <name>prisca::app::ModalDialog</name>
    <message>
        <location filename="../app/widgets/ModalDialog.cpp" line="59"/>
        <source>%1 already exists.
Do you want to replace it?</source>
        <translation>%1 已存在。
要取代它嗎？</translation>
    </message>
</context>
<context>
    <name>prisca::app::ModelPanel</name>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="122"/>
        <location filename="../app/panels/ModelPanel.cpp" line="135"/>
        <location filename="../app/panels/ModelPanel.cpp" line="143"/>
        <location filename="../app/panels/ModelPanel.cpp" line="182"/>
        <location filename="../app/panels/ModelPanel.cpp" line="203"/>
        <location filename="../app/panels/ModelPanel.cpp" line="211"/>
        <location filename="../app/panels/ModelPanel.cpp" line="282"/>
        <location filename="../app/panels/ModelPanel.cpp" line="296"/>
        <location filename="../app/panels/ModelPanel.cpp" line="309"/>
        <location filename="../app/panels/ModelPanel.cpp" line="310"/>
        <location filename="../app/panels/ModelPanel.cpp" line="316"/>
        <source>Model</source>
        <translation>模型</translation>
    </message>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="122"/>
        <location filename="../app/panels/ModelPanel.cpp" line="123"/>
        <source>The identification failed: %1</source>
        <translation>辨識失敗：%1</translation>
    </message>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="136"/>
        <source>E-STOP: the identification is cancelled; the session keeps the model it had.</source>
        <translation>緊急停止：辨識已取消；工作階段保留原有的模型。</translation>
    </message>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="144"/>
        <source>The identified model was cleared: %1. Identify again for mpc to plan through a model of this car.</source>
        <translation>已辨識的模型已清除：%1。請重新辨識，讓 mpc 以這輛車的模型規劃。</translation>
    </message>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="204"/>
        <source>Identifying the car from %1...</source>
        <translation>正在從%1辨識車輛……</translation>
    </message>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="211"/>
        <source>Cancelling the identification...</source>
        <translation>正在取消辨識……</translation>
    </message>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="252"/>
        <source>Identifying... %1 so far</source>
        <translation>正在辨識……已用 %1</translation>
    </message>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="253"/>
        <source>Identifying: %1 of about %2 model runs · %3</source>
        <translation>正在辨識：約 %2 次模型運算中已完成 %1 次 · %3</translation>
    </message>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="260"/>
        <source>E-STOP: cancelling. %1</source>
        <translation>緊急停止：正在取消。%1</translation>
    </message>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="262"/>
        <source>Cancelling. %1</source>
        <translation>正在取消。%1</translation>
    </message>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="279"/>
        <source>Cancelled</source>
        <translation>已取消</translation>
    </message>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="283"/>
        <source>Stopped by E-STOP after %1.</source>
        <translation>%1 後被緊急停止。</translation>
    </message>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="284"/>
        <source>Cancelled after %1: the demonstration or the car changed.</source>
        <translation>%1 後已取消：示範或車輛已改變。</translation>
    </message>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="287"/>
        <source>Cancelled after %1.</source>
        <translation>%1 後已取消。</translation>
    </message>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="290"/>
        <source>The model identified before is kept.</source>
        <translation>之前辨識的模型已保留。</translation>
    </message>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="290"/>
        <source>No model was kept.</source>
        <translation>沒有保留任何模型。</translation>
    </message>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="293"/>
        <source>Refused</source>
        <translation>已拒絕</translation>
    </message>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="298"/>
        <source>This demonstration cannot identify the car: %1. Record one that drives the car through a slide, with throttle and steering that change.</source>
        <translation>此示範無法辨識車輛：%1。請錄製一段令車輛打滑、油門和轉向都有變化的示範。</translation>
    </message>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="307"/>
        <source>Done</source>
        <translation>完成</translation>
    </message>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="311"/>
        <source>Identified in %1; mpc plans through the new model.</source>
        <translation>用 %1 完成辨識；mpc 以新模型規劃。</translation>
    </message>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="345"/>
        <source>Model: pose error %1 cm RMS per segment over %2 segments (the prior&apos;s %3 cm); %4 of %5 fitted parameters identified, the rest held at their prior or, where the data reject it, undetermined. mpc plans through this model.</source>
        <translation>模型：%2 個分段的每段位姿誤差均方根為 %1 cm（先驗模型為 %3 cm）；%5 個擬合參數中 %4 個已辨識，其餘保持先驗值，或在數據否定先驗值時列為未確定。mpc 以此模型規劃。</translation>
    </message>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="370"/>
        <source>held</source>
        <translation>保持</translation>
    </message>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="371"/>
        <source>undetermined</source>
        <translation>未能確定</translation>
    </message>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="387"/>
        <source>%1: identified (prior %2)</source>
        <translation>%1：已辨識（先驗值 %2）</translation>
    </message>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="389"/>
        <source>%1: the data did not determine it; held at its prior</source>
        <translation>%1：數據未能確定其值；保持先驗值</translation>
    </message>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="390"/>
        <source>%1: fitted, but the data did not determine it</source>
        <translation>%1：已擬合，但數據未能確定其值</translation>
    </message>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="428"/>
        <source>model, replaying the recorded actions</source>
        <translation>模型，重播錄得的動作</translation>
    </message>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="488"/>
        <source>Fits the car&apos;s physical parameters to the demonstration (as prisca-cli identify). mpc plans through the model; the session saves it.</source>
        <translation>把車輛的物理參數擬合到示範（與 prisca-cli identify 相同）。mpc 以此模型規劃；工作階段會儲存它。</translation>
    </message>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="317"/>
        <source>The model identified was not kept: %1.</source>
        <translation>辨識出的模型未有保留：%1。</translation>
    </message>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="331"/>
        <source>Only the slide-car can be identified: the %1 has no model to identify here, and mpc does not run on it.</source>
        <translation>只有漂移車可以辨識：%1 在此沒有可辨識的模型，mpc 亦不能在其上運行。</translation>
    </message>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="336"/>
        <source>No model yet. Identify fits the car&apos;s friction, grip, drive, steering and delays to the demonstration; until then a simulated run of mpc identifies one itself as it starts, and the rig waits for one.</source>
        <translation>尚未有模型。「辨識」會把車輛的摩擦、抓地力、驅動、轉向及延遲擬合到示範；在此之前，mpc 的模擬運行會在開始時自行辨識一個模型，而實驗台則會等候模型。</translation>
    </message>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="369"/>
        <source>identified</source>
        <translation>已辨識</translation>
    </message>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="398"/>
        <source>Not fitted (measured, or the catalog&apos;s): %1</source>
        <translation>未擬合（量度所得或目錄值）：%1</translation>
    </message>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="406"/>
        <source>x [m]</source>
        <translation>x [m]</translation>
    </message>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="407"/>
        <source>y [m]</source>
        <translation>y [m]</translation>
    </message>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="408"/>
        <source>no path</source>
        <translation>沒有路徑</translation>
    </message>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="421"/>
        <source>recorded</source>
        <translation>錄得</translation>
    </message>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="490"/>
        <source>Identify</source>
        <translation>辨識</translation>
    </message>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="491"/>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="493"/>
        <source>Parameter</source>
        <translation>參數</translation>
    </message>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="493"/>
        <source>Value</source>
        <translation>數值</translation>
    </message>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="493"/>
        <source>Unit</source>
        <translation>單位</translation>
    </message>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="493"/>
        <source>Std. dev.</source>
        <translation>標準差</translation>
    </message>
    <message>
        <location filename="../app/panels/ModelPanel.cpp" line="493"/>
        <source>Verdict</source>
        <translation>判定</translation>
    </message>
</context>
<context>
    <name>prisca::app::RecordPanel</name>
    <message>
        <location filename="../app/panels/RecordPanel.cpp" line="95"/>
        <location filename="../app/panels/RecordPanel.cpp" line="135"/>
        <location filename="../app/panels/RecordPanel.cpp" line="161"/>
        <location filename="../app/panels/RecordPanel.cpp" line="168"/>
        <location filename="../app/panels/RecordPanel.cpp" line="221"/>
        <location filename="../app/panels/RecordPanel.cpp" line="250"/>
        <location filename="../app/panels/RecordPanel.cpp" line="262"/>
        <location filename="../app/panels/RecordPanel.cpp" line="279"/>
        <location filename="../app/panels/RecordPanel.cpp" line="287"/>
        <location filename="../app/panels/RecordPanel.cpp" line="315"/>
        <location filename="../app/panels/RecordPanel.cpp" line="326"/>
        <location filename="../app/panels/RecordPanel.cpp" line="359"/>
        <source>Record</source>
        <translation>錄製</translation>
    </message>
    <message>
        <location filename="../app/panels/RecordPanel.cpp" line="162"/>
        <source>Recording... drive, then press Stop.</source>
        <translation>錄製中……請駕駛，完成後按「停止」。</translation>
    </message>
    <message>
        <location filename="../app/panels/RecordPanel.cpp" line="169"/>
        <source>Recording starts in %1 s</source>
        <translation>%1 秒後開始錄製</translation>
    </message>
    <message>
        <location filename="../app/panels/RecordPanel.cpp" line="205"/>
        <source>Recording %1 s: %2. Press Stop when done.</source>
        <translation>錄製中 %1 秒：%2。完成後按停止。</translation>
    </message>
    <message>
        <location filename="../app/panels/RecordPanel.cpp" line="210"/>
        <source>The car has no brakes: let go of the throttle early, it slides on.</source>
        <translation>此車沒有煞車：請提早放開油門，車會繼續滑行。</translation>
    </message>
    <message>
        <location filename="../app/panels/RecordPanel.cpp" line="221"/>
        <source>Recording cancelled.</source>
        <translation>已取消錄製。</translation>
    </message>
    <message>
        <location filename="../app/panels/RecordPanel.cpp" line="252"/>
        <source>E-STOP ended the recording; nothing was recorded.</source>
        <translation>緊急停止結束了錄製；沒有錄得任何內容。</translation>
    </message>
    <message>
        <location filename="../app/panels/RecordPanel.cpp" line="253"/>
        <source>E-STOP ended the recording after %1 s; the demonstration is unchanged. The take is kept in %2 (open it from the Task panel to use it).</source>
        <translation>緊急停止在 %1 秒後結束了錄製；示範未有改變。該次錄製保存在 %2（可在任務面板開啟使用）。</translation>
    </message>
    <message>
        <location filename="../app/panels/RecordPanel.cpp" line="264"/>
        <source>Nothing recorded.</source>
        <translation>沒有錄得任何內容。</translation>
    </message>
    <message>
        <location filename="../app/panels/RecordPanel.cpp" line="265"/>
        <source>Too short to use (%1 samples, at least %2 are needed); the demonstration is unchanged.</source>
        <translation>太短無法使用（%1 個樣本，至少需要 %2 個）；示範未有改變。</translation>
    </message>
    <message>
        <location filename="../app/panels/RecordPanel.cpp" line="280"/>
        <source>The recording could not be used: %1. It is kept in %2.</source>
        <translation>錄製無法使用：%1。檔案保留在 %2。</translation>
    </message>
    <message>
        <location filename="../app/panels/RecordPanel.cpp" line="290"/>
        <source>Recorded %1 samples (%2 s), kept in %3. It is now the demonstration; save it or discard it.</source>
        <translation>已錄得 %1 個樣本（%2 秒），保存在 %3。它現在是示範；請儲存或捨棄。</translation>
    </message>
    <message>
        <location filename="../app/panels/RecordPanel.cpp" line="300"/>
        <location filename="../app/panels/RecordPanel.cpp" line="311"/>
        <source>Save demonstration</source>
        <translation>儲存示範</translation>
    </message>
    <message>
        <location filename="../app/panels/RecordPanel.cpp" line="302"/>
        <source>Demonstrations (*.csv)</source>
        <translation>示範 (*.csv)</translation>
    </message>
    <message>
        <location filename="../app/panels/RecordPanel.cpp" line="315"/>
        <source>Saved %1</source>
        <translation>已儲存 %1</translation>
    </message>
    <message>
        <location filename="../app/panels/RecordPanel.cpp" line="327"/>
        <source>Recording discarded; the previous demonstration is back.</source>
        <translation>已捨棄錄製；已恢復先前的示範。</translation>
    </message>
    <message>
        <location filename="../app/panels/RecordPanel.cpp" line="349"/>
        <source>Drive with ↑/W and ↓/S for %1, ←/A and →/D for %2. Space or Esc is E-STOP.</source>
        <translation>用 ↑/W 和 ↓/S 控制 %1，←/A 和 →/D 控制 %2。空格鍵或 Esc 為緊急停止。</translation>
    </message>
    <message>
        <location filename="../app/panels/RecordPanel.cpp" line="354"/>
        <source>Gamepad: %1 (left stick forward, right stick sideways)</source>
        <translation>遊戲手柄：%1（左搖桿前後，右搖桿左右）</translation>
    </message>
    <message>
        <location filename="../app/panels/RecordPanel.cpp" line="356"/>
        <source>No gamepad found: the keyboard drives.</source>
        <translation>找不到遊戲手柄：以鍵盤駕駛。</translation>
    </message>
    <message>
        <location filename="../app/panels/RecordPanel.cpp" line="357"/>
        <source>Countdown:</source>
        <translation>倒數：</translation>
    </message>
    <message>
        <location filename="../app/panels/RecordPanel.cpp" line="358"/>
        <source> s</source>
        <translation> 秒</translation>
    </message>
    <message>
        <location filename="../app/panels/RecordPanel.cpp" line="360"/>
        <source>Count down, then record while you drive</source>
        <translation>倒數後，一邊駕駛一邊錄製</translation>
    </message>
    <message>
        <location filename="../app/panels/RecordPanel.cpp" line="361"/>
        <source>Stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <location filename="../app/panels/RecordPanel.cpp" line="362"/>
        <source>Save as...</source>
        <translation>另存為...</translation>
    </message>
    <message>
        <location filename="../app/panels/RecordPanel.cpp" line="363"/>
        <source>Discard</source>
        <translation>捨棄</translation>
    </message>
    <message>
        <location filename="../app/panels/RecordPanel.cpp" line="364"/>
        <source>Delete this recording and go back to the previous demonstration</source>
        <translation>刪除此錄製並返回先前的示範</translation>
    </message>
</context>
<context>
    <name>prisca::app::RecordingWorker</name>
    <message>
        <location filename="../app/workers/RecordingWorker.cpp" line="44"/>
        <source>Cannot record to %1</source>
        <translation>無法錄製到 %1</translation>
    </message>
    <message>
        <location filename="../app/workers/RecordingWorker.cpp" line="117"/>
        <source>Writing the recording failed: %1 (the take so far is in %2)</source>
        <translation>寫入錄製失敗：%1（目前錄得的內容在 %2）</translation>
    </message>
</context>
<context>
    <name>prisca::app::ReplayDialog</name>
    <message>
        <location filename="../app/panels/ReplayDialog.cpp" line="42"/>
        <source>Replay: %1</source>
        <translation>重播：%1</translation>
    </message>
    <message>
        <location filename="../app/panels/ReplayDialog.cpp" line="100"/>
        <source>distance from the path [m]</source>
        <translation>與路徑的距離 [米]</translation>
    </message>
    <message>
        <location filename="../app/panels/ReplayDialog.cpp" line="101"/>
        <source>now</source>
        <translation>現在</translation>
    </message>
    <message>
        <location filename="../app/panels/ReplayDialog.cpp" line="104"/>
        <source>trial time [s]</source>
        <translation>試驗時間 [秒]</translation>
    </message>
    <message>
        <location filename="../app/panels/ReplayDialog.cpp" line="105"/>
        <source>error [m]</source>
        <translation>誤差 [米]</translation>
    </message>
    <message>
        <location filename="../app/panels/ReplayDialog.cpp" line="130"/>
        <source>Pause</source>
        <translation>暫停</translation>
    </message>
    <message>
        <location filename="../app/panels/ReplayDialog.cpp" line="130"/>
        <location filename="../app/panels/ReplayDialog.cpp" line="136"/>
        <location filename="../app/panels/ReplayDialog.cpp" line="141"/>
        <source>Play</source>
        <translation>播放</translation>
    </message>
    <message>
        <location filename="../app/panels/ReplayDialog.cpp" line="144"/>
        <source>%1 trial, %2: %3 samples, %4 frames, %5 s</source>
        <translation>%1 試驗，%2：%3 個樣本，%4 個影格，%5 秒</translation>
    </message>
    <message>
        <location filename="../app/panels/ReplayDialog.cpp" line="150"/>
        <source>; last pose %1 cm, %2° from the lot</source>
        <translation>；最後位姿距泊車位 %1 厘米、%2°</translation>
    </message>
    <message>
        <location filename="../app/panels/ReplayDialog.cpp" line="156"/>
        <source> (incomplete: the writer stopped before the trial ended)</source>
        <translation>（不完整：試驗結束前寫入已停止）</translation>
    </message>
    <message>
        <location filename="../app/panels/ReplayDialog.cpp" line="158"/>
        <source>; ended in failsafe: %1</source>
        <translation>；以失效保護結束：%1</translation>
    </message>
    <message>
        <location filename="../app/panels/ReplayDialog.cpp" line="189"/>
        <source>no samples</source>
        <translation>沒有樣本</translation>
    </message>
    <message>
        <location filename="../app/panels/ReplayDialog.cpp" line="232"/>
        <source>%1 s, frame %2%3</source>
        <translation>%1 秒，影格 %2%3</translation>
    </message>
    <message>
        <location filename="../app/panels/ReplayDialog.cpp" line="235"/>
        <source>, failsafe</source>
        <translation>，失效保護</translation>
    </message>
</context>
<context>
    <name>prisca::app::RigCameraPage</name>
    <message>
        <location filename="../app/rig/RigCameraPage.cpp" line="105"/>
        <source>Open floor calibration</source>
        <translation>開啟地面校準</translation>
    </message>
    <message>
        <location filename="../app/rig/RigCameraPage.cpp" line="106"/>
        <location filename="../app/rig/RigCameraPage.cpp" line="113"/>
        <source>Calibrations (*.json)</source>
        <translation>校準 (*.json)</translation>
    </message>
    <message>
        <location filename="../app/rig/RigCameraPage.cpp" line="112"/>
        <source>Save floor calibration</source>
        <translation>儲存地面校準</translation>
    </message>
    <message>
        <location filename="../app/rig/RigCameraPage.cpp" line="121"/>
        <location filename="../app/rig/RigCameraPage.cpp" line="210"/>
        <location filename="../app/rig/RigCameraPage.cpp" line="220"/>
        <location filename="../app/rig/RigCameraPage.cpp" line="230"/>
        <location filename="../app/rig/RigCameraPage.cpp" line="240"/>
        <source>Floor calibration</source>
        <translation>地面校準</translation>
    </message>
    <message>
        <location filename="../app/rig/RigCameraPage.cpp" line="122"/>
        <source>Calibrating: click a mark on the camera image whose floor position you know, then type it (x, y in metres). Four or more marks spread over the floor; the fit updates with each. Click Calibrate again when done.</source>
        <translation>校準中：在攝影機影像上點選一個已知地面位置的標記，然後輸入其位置（x, y，單位米）。需四個或以上分佈在地面上的標記；每加一個，擬合便會更新。完成後再按「校準」。</translation>
    </message>
    <message>
        <location filename="../app/rig/RigCameraPage.cpp" line="132"/>
        <location filename="../app/rig/RigCameraPage.cpp" line="138"/>
        <location filename="../app/rig/RigCameraPage.cpp" line="146"/>
        <location filename="../app/rig/RigCameraPage.cpp" line="203"/>
        <location filename="../app/rig/RigCameraPage.cpp" line="212"/>
        <source>Camera</source>
        <translation>攝影機</translation>
    </message>
    <message>
        <location filename="../app/rig/RigCameraPage.cpp" line="139"/>
        <source>The video ended after %1 frames; Start plays it again.</source>
        <translation>影片在 %1 幀後結束；按「開始」再次播放。</translation>
    </message>
    <message>
        <location filename="../app/rig/RigCameraPage.cpp" line="146"/>
        <source>Camera stopped.</source>
        <translation>攝影機已停止。</translation>
    </message>
    <message>
        <location filename="../app/rig/RigCameraPage.cpp" line="212"/>
        <source>Camera started: %1</source>
        <translation>攝影機已啟動：%1</translation>
    </message>
    <message>
        <location filename="../app/rig/RigCameraPage.cpp" line="248"/>
        <location filename="../app/rig/RigCameraPage.cpp" line="256"/>
        <source>Floor point</source>
        <translation>地面點</translation>
    </message>
    <message>
        <location filename="../app/rig/RigCameraPage.cpp" line="249"/>
        <source>Where is this point on the floor? x, y in metres (e.g. 1.5, -0.2):</source>
        <translation>此點在地面的位置？x, y（米，例如 1.5, -0.2）：</translation>
    </message>
    <message>
        <location filename="../app/rig/RigCameraPage.cpp" line="287"/>
        <source>Camera:</source>
        <translation>攝影機：</translation>
    </message>
    <message>
        <location filename="../app/rig/RigCameraPage.cpp" line="288"/>
        <source>Virtual rig (synthetic camera, simulated car)</source>
        <translation>虛擬實機（合成攝影機，模擬車輛）</translation>
    </message>
    <message>
        <location filename="../app/rig/RigCameraPage.cpp" line="289"/>
        <source>Camera device (V4L2)</source>
        <translation>攝影機裝置 (V4L2)</translation>
    </message>
    <message>
        <location filename="../app/rig/RigCameraPage.cpp" line="290"/>
        <source>Video file</source>
        <translation>影片檔案</translation>
    </message>
    <message>
        <location filename="../app/rig/RigCameraPage.cpp" line="296"/>
        <source>Device:</source>
        <translation>裝置：</translation>
    </message>
    <message>
        <location filename="../app/rig/RigCameraPage.cpp" line="297"/>
        <source>Width [px] asked of the camera</source>
        <translation>要求攝影機的寬度 [px]</translation>
    </message>
    <message>
        <location filename="../app/rig/RigCameraPage.cpp" line="298"/>
        <source>Height [px] asked of the camera</source>
        <translation>要求攝影機的高度 [px]</translation>
    </message>
    <message>
        <location filename="../app/rig/RigCameraPage.cpp" line="299"/>
        <source> fps</source>
        <translation> fps</translation>
    </message>
    <message>
        <location filename="../app/rig/RigCameraPage.cpp" line="300"/>
        <source>Frame rate asked of the camera</source>
        <translation>要求攝影機的幀率</translation>
    </message>
    <message>
        <location filename="../app/rig/RigCameraPage.cpp" line="301"/>
        <source>auto exposure</source>
        <translation>自動曝光</translation>
    </message>
    <message>
        <location filename="../app/rig/RigCameraPage.cpp" line="303"/>
        <source>Exposure in the driver&apos;s units; lowest: the driver&apos;s automatic exposure. IR LEDs track best with a short exposure.</source>
        <translation>曝光（驅動程式單位）；最低值：由驅動程式自動曝光。紅外 LED 在短曝光下追蹤效果最好。</translation>
    </message>
    <message>
        <location filename="../app/rig/RigCameraPage.cpp" line="305"/>
        <source>auto gain</source>
        <translation>自動增益</translation>
    </message>
    <message>
        <location filename="../app/rig/RigCameraPage.cpp" line="306"/>
        <source>Gain in the driver&apos;s units; lowest: leave the driver&apos;s</source>
        <translation>增益（驅動程式單位）；最低值：保留驅動程式的設定</translation>
    </message>
    <message>
        <location filename="../app/rig/RigCameraPage.cpp" line="307"/>
        <source>/dev/video0</source>
        <translation>/dev/video0</translation>
    </message>
    <message>
        <location filename="../app/rig/RigCameraPage.cpp" line="308"/>
        <source>path of a video file</source>
        <translation>影片檔案路徑</translation>
    </message>
    <message>
        <location filename="../app/rig/RigCameraPage.cpp" line="310"/>
        <source>Open...</source>
        <translation>開啟...</translation>
    </message>
    <message>
        <location filename="../app/rig/RigCameraPage.cpp" line="311"/>
        <source>Save...</source>
        <translation>儲存...</translation>
    </message>
    <message>
        <location filename="../app/rig/RigCameraPage.cpp" line="312"/>
        <source>Calibrate</source>
        <translation>校準</translation>
    </message>
    <message>
        <location filename="../app/rig/RigCameraPage.cpp" line="314"/>
        <source>Click four or more floor points of known position on the camera image</source>
        <translation>在攝影機影像上點擊四個或以上已知位置的地面點</translation>
    </message>
</context>
<context>
    <name>prisca::app::RigDoctorPage</name>
    <message>
        <location filename="../app/rig/RigDoctorPage.cpp" line="85"/>
        <source>Checking this computer...</source>
        <translation>正在檢查這部電腦……</translation>
    </message>
    <message>
        <location filename="../app/rig/RigDoctorPage.cpp" line="99"/>
        <source>This computer</source>
        <translation>這部電腦</translation>
    </message>
    <message>
        <location filename="../app/rig/RigDoctorPage.cpp" line="101"/>
        <source>The rig has what it needs on this computer.</source>
        <translation>這部電腦具備實機所需的一切。</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/rig/RigDoctorPage.cpp" line="102"/>
        <source>%n line(s) to fix before the rig can run.</source>
        <translation>
            <numerusform>實機運行前有 %n 項須修正。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/rig/RigDoctorPage.cpp" line="115"/>
        <source>OK</source>
        <translation>正常</translation>
    </message>
    <message>
        <location filename="../app/rig/RigDoctorPage.cpp" line="115"/>
        <source>Fix</source>
        <translation>須修正</translation>
    </message>
    <message>
        <location filename="../app/rig/RigDoctorPage.cpp" line="115"/>
        <source>Note</source>
        <translation>注意</translation>
    </message>
    <message>
        <location filename="../app/rig/RigDoctorPage.cpp" line="143"/>
        <source>Check this computer</source>
        <translation>檢查這部電腦</translation>
    </message>
    <message>
        <location filename="../app/rig/RigDoctorPage.cpp" line="145"/>
        <source>The serial ports and whether you may open them, the cameras, the display and the free space: what prisca-cli doctor checks</source>
        <translation>序列埠及你能否開啟它們、攝影機、顯示器及可用空間：即 prisca-cli doctor 所檢查的項目</translation>
    </message>
    <message>
        <location filename="../app/rig/RigDoctorPage.cpp" line="147"/>
        <source>What</source>
        <translation>項目</translation>
    </message>
    <message>
        <location filename="../app/rig/RigDoctorPage.cpp" line="147"/>
        <source>Found, or what to do</source>
        <translation>結果，或應如何處理</translation>
    </message>
    <message>
        <location filename="../app/rig/RigDoctorPage.cpp" line="149"/>
        <source>Not checked yet.</source>
        <translation>尚未檢查。</translation>
    </message>
</context>
<context>
    <name>prisca::app::RigLinkPage</name>
    <message>
        <location filename="../app/rig/RigLinkPage.cpp" line="44"/>
        <location filename="../app/rig/RigLinkPage.cpp" line="164"/>
        <source>PPM bridge (trainer port)</source>
        <translation>PPM 橋接（教練接口）</translation>
    </message>
    <message>
        <location filename="../app/rig/RigLinkPage.cpp" line="74"/>
        <location filename="../app/rig/RigLinkPage.cpp" line="144"/>
        <source>Link</source>
        <translation>鏈路</translation>
    </message>
    <message>
        <location filename="../app/rig/RigLinkPage.cpp" line="74"/>
        <source>Choose or type the transmitter&apos;s port first.</source>
        <translation>請先選擇或輸入發射器的連接埠。</translation>
    </message>
    <message>
        <location filename="../app/rig/RigLinkPage.cpp" line="117"/>
        <source>Link: connected, %1 frames/s, %2 sent</source>
        <translation>連線：已連接，每秒 %1 幀，已發送 %2</translation>
    </message>
    <message>
        <location filename="../app/rig/RigLinkPage.cpp" line="120"/>
        <location filename="../app/rig/RigLinkPage.cpp" line="129"/>
        <source>Link: not connected</source>
        <translation>連線：未連接</translation>
    </message>
    <message>
        <location filename="../app/rig/RigLinkPage.cpp" line="122"/>
        <location filename="../app/rig/RigLinkPage.cpp" line="131"/>
        <source>; failsafe (%1)</source>
        <translation>；失效保護（%1）</translation>
    </message>
    <message>
        <location filename="../app/rig/RigLinkPage.cpp" line="129"/>
        <source>Link: connected</source>
        <translation>鏈路：已連接</translation>
    </message>
    <message>
        <location filename="../app/rig/RigLinkPage.cpp" line="157"/>
        <source>Transmitter port:</source>
        <translation>發射器連接埠：</translation>
    </message>
    <message>
        <location filename="../app/rig/RigLinkPage.cpp" line="158"/>
        <source>A serial port found on this computer, or type a device path</source>
        <translation>本機找到的序列埠，或輸入裝置路徑</translation>
    </message>
    <message>
        <location filename="../app/rig/RigLinkPage.cpp" line="159"/>
        <source>Protocol:</source>
        <translation>協定：</translation>
    </message>
    <message>
        <location filename="../app/rig/RigLinkPage.cpp" line="160"/>
        <source>Baud rate:</source>
        <translation>波特率：</translation>
    </message>
    <message>
        <location filename="../app/rig/RigLinkPage.cpp" line="161"/>
        <source>protocol default</source>
        <translation>協定預設</translation>
    </message>
    <message>
        <location filename="../app/rig/RigLinkPage.cpp" line="162"/>
        <source>0: the protocol&apos;s own (CRSF 420000; SBUS and Multiprotocol 100000 8E2)</source>
        <translation>0：協定本身的設定（CRSF 420000；SBUS 及 Multiprotocol 100000 8E2）</translation>
    </message>
</context>
<context>
    <name>prisca::app::RigPanel</name>
    <message>
        <location filename="../app/rig/RigPanel.cpp" line="313"/>
        <source>Trial %1 running...</source>
        <translation>第 %1 次試驗進行中...</translation>
    </message>
    <message>
        <location filename="../app/rig/RigPanel.cpp" line="396"/>
        <source>Driving and recording: arrows or WASD (or a gamepad); press Drive again to stop.</source>
        <translation>駕駛並錄製中：方向鍵或 WASD（或遊戲手柄）；再按「駕駛」即停止。</translation>
    </message>
    <message>
        <location filename="../app/rig/RigPanel.cpp" line="436"/>
        <source>The rig recording could not be used: %1. It is kept in %2.</source>
        <translation>實驗台錄製無法使用：%1。檔案保留在 %2。</translation>
    </message>
    <message>
        <location filename="../app/rig/RigPanel.cpp" line="431"/>
        <source>Recorded %1 samples on the rig, kept in %2; it is now the demonstration.</source>
        <translation>已在實機上錄得 %1 個樣本，保存在 %2；它現在是示範。</translation>
    </message>
    <message>
        <location filename="../app/rig/RigPanel.cpp" line="190"/>
        <source>Fence: click its corners in order around the floor; click Draw fence again to finish</source>
        <translation>圍欄：沿地面依次點擊各角；再按「繪畫圍欄」完成</translation>
    </message>
    <message>
        <location filename="../app/rig/RigPanel.cpp" line="415"/>
        <source>Saving the recording...</source>
        <translation>正在儲存錄製內容...</translation>
    </message>
    <message>
        <location filename="../app/rig/RigPanel.cpp" line="424"/>
        <source>E-STOP ended the rig recording; the demonstration is unchanged. The take is kept in %1.</source>
        <translation>緊急停止結束了實機錄製；示範未有改變。該次錄製保存在 %1。</translation>
    </message>
    <message>
        <location filename="../app/rig/RigPanel.cpp" line="457"/>
        <source>E-STOP: the transmitter sends failsafe until E-STOP is reset.</source>
        <translation>緊急停止：在重設緊急停止之前，發射器會一直發送失效保護訊號。</translation>
    </message>
    <message>
        <location filename="../app/rig/RigPanel.cpp" line="170"/>
        <location filename="../app/rig/RigPanel.cpp" line="288"/>
        <location filename="../app/rig/RigPanel.cpp" line="295"/>
        <location filename="../app/rig/RigPanel.cpp" line="304"/>
        <location filename="../app/rig/RigPanel.cpp" line="310"/>
        <location filename="../app/rig/RigPanel.cpp" line="313"/>
        <location filename="../app/rig/RigPanel.cpp" line="357"/>
        <location filename="../app/rig/RigPanel.cpp" line="360"/>
        <location filename="../app/rig/RigPanel.cpp" line="373"/>
        <location filename="../app/rig/RigPanel.cpp" line="378"/>
        <location filename="../app/rig/RigPanel.cpp" line="389"/>
        <location filename="../app/rig/RigPanel.cpp" line="395"/>
        <location filename="../app/rig/RigPanel.cpp" line="415"/>
        <location filename="../app/rig/RigPanel.cpp" line="441"/>
        <location filename="../app/rig/RigPanel.cpp" line="453"/>
        <location filename="../app/rig/RigPanel.cpp" line="464"/>
        <location filename="../app/rig/RigPanel.cpp" line="470"/>
        <source>Rig trial</source>
        <translation>實驗台試驗</translation>
    </message>
    <message>
        <location filename="../app/rig/RigPanel.cpp" line="586"/>
        <source>Link</source>
        <translation>鏈路</translation>
    </message>
    <message>
        <location filename="../app/rig/RigPanel.cpp" line="192"/>
        <source>Floor calibration: click a point of known floor position</source>
        <translation>地面校準：點選一個已知地面位置的點</translation>
    </message>
    <message>
        <location filename="../app/rig/RigPanel.cpp" line="296"/>
        <source>Not ready for a trial: %1</source>
        <translation>未能進行試驗：%1</translation>
    </message>
    <message>
        <location filename="../app/rig/RigPanel.cpp" line="339"/>
        <source>Ready for a trial</source>
        <translation>可以進行試驗</translation>
    </message>
    <message>
        <location filename="../app/rig/RigPanel.cpp" line="340"/>
        <source>Ready for a trial (note: %1)</source>
        <translation>可以進行試驗（注意：%1）</translation>
    </message>
    <message>
        <location filename="../app/rig/RigPanel.cpp" line="342"/>
        <source>Not ready: %1</source>
        <translation>未準備好：%1</translation>
    </message>
    <message>
        <location filename="../app/rig/RigPanel.cpp" line="360"/>
        <source>The virtual car is back at its start.</source>
        <translation>虛擬車已回到起點。</translation>
    </message>
    <message>
        <location filename="../app/rig/RigPanel.cpp" line="465"/>
        <source>E-STOP is reset: the link sends the commands again.</source>
        <translation>緊急停止已重設：鏈路再次發送指令。</translation>
    </message>
    <message>
        <location filename="../app/rig/RigPanel.cpp" line="492"/>
        <source>Link: off</source>
        <translation>鏈路：關閉</translation>
    </message>
    <message>
        <location filename="../app/rig/RigPanel.cpp" line="492"/>
        <source>Link: port error</source>
        <translation>鏈路：連接埠錯誤</translation>
    </message>
    <message>
        <location filename="../app/rig/RigPanel.cpp" line="495"/>
        <source>Link: %1 failsafe (%2)</source>
        <translation>鏈路：%1 失效保護（%2）</translation>
    </message>
    <message>
        <location filename="../app/rig/RigPanel.cpp" line="500"/>
        <source>Link: %1 %2/s</source>
        <translation>鏈路：%1 %2/s</translation>
    </message>
    <message>
        <location filename="../app/rig/RigPanel.cpp" line="505"/>
        <source>Camera: %1 fps, tracking</source>
        <translation>攝影機：%1 fps，追蹤中</translation>
    </message>
    <message>
        <location filename="../app/rig/RigPanel.cpp" line="506"/>
        <source>Camera: %1 fps, no car in view</source>
        <translation>攝影機：%1 fps，視野內沒有車</translation>
    </message>
    <message>
        <location filename="../app/rig/RigPanel.cpp" line="509"/>
        <source>Camera: failed</source>
        <translation>攝影機：失敗</translation>
    </message>
    <message>
        <location filename="../app/rig/RigPanel.cpp" line="510"/>
        <source>Camera: video ended</source>
        <translation>攝影機：影片已結束</translation>
    </message>
    <message>
        <location filename="../app/rig/RigPanel.cpp" line="511"/>
        <source>Camera: off</source>
        <translation>攝影機：關閉</translation>
    </message>
    <message>
        <location filename="../app/rig/RigPanel.cpp" line="537"/>
        <source>the process being stopped and continued</source>
        <translation>程式被暫停後再繼續</translation>
    </message>
    <message>
        <location filename="../app/rig/RigPanel.cpp" line="568"/>
        <source>Start camera</source>
        <translation>啟動攝影機</translation>
    </message>
    <message>
        <location filename="../app/rig/RigPanel.cpp" line="569"/>
        <source>Stop camera</source>
        <translation>停止攝影機</translation>
    </message>
    <message>
        <location filename="../app/rig/RigPanel.cpp" line="570"/>
        <source>Connect</source>
        <translation>連接</translation>
    </message>
    <message>
        <location filename="../app/rig/RigPanel.cpp" line="571"/>
        <source>Disconnect</source>
        <translation>中斷連接</translation>
    </message>
    <message>
        <location filename="../app/rig/RigPanel.cpp" line="572"/>
        <source>Drive and record</source>
        <translation>駕駛並錄製</translation>
    </message>
    <message>
        <location filename="../app/rig/RigPanel.cpp" line="574"/>
        <source>Drive the car through the link (arrows or WASD, or a gamepad) and record a demonstration from the camera</source>
        <translation>經連線駕駛車輛（方向鍵或 WASD，或遊戲手柄），並由攝影機錄製示範</translation>
    </message>
    <message>
        <location filename="../app/rig/RigPanel.cpp" line="576"/>
        <source>Run a trial on the rig</source>
        <translation>在實機上運行一次試驗</translation>
    </message>
    <message>
        <location filename="../app/rig/RigPanel.cpp" line="578"/>
        <source>The session&apos;s method drives the car through the link, with the camera&apos;s pose as its state</source>
        <translation>以攝影機測得的位姿作為狀態，由工作階段的方法經連線驅動車輛</translation>
    </message>
    <message>
        <location filename="../app/rig/RigPanel.cpp" line="580"/>
        <source>Stop the trial</source>
        <translation>停止試驗</translation>
    </message>
    <message>
        <location filename="../app/rig/RigPanel.cpp" line="585"/>
        <source>Camera and floor</source>
        <translation>攝影機與地面</translation>
    </message>
    <message>
        <location filename="../app/rig/RigPanel.cpp" line="587"/>
        <source>Lens, latency, fence</source>
        <translation>鏡頭、延遲、圍欄</translation>
    </message>
    <message>
        <location filename="../app/rig/RigPanel.cpp" line="588"/>
        <source>This computer</source>
        <translation>這部電腦</translation>
    </message>
    <message>
        <location filename="../app/rig/RigPanel.cpp" line="581"/>
        <source>Put the car back</source>
        <translation>把車放回起點</translation>
    </message>
    <message>
        <location filename="../app/rig/RigPanel.cpp" line="583"/>
        <source>The virtual car back at its start, at rest (after a trial that left it out of view)</source>
        <translation>把虛擬車靜止放回起點（試驗後車駛出畫面時用）</translation>
    </message>
</context>
<context>
    <name>prisca::app::RigSetupPage</name>
    <message>
        <location filename="../app/rig/RigSetupPage.cpp" line="96"/>
        <location filename="../app/rig/RigSetupPage.cpp" line="244"/>
        <source>Open camera intrinsics</source>
        <translation>開啟攝影機內參</translation>
    </message>
    <message>
        <location filename="../app/rig/RigSetupPage.cpp" line="97"/>
        <location filename="../app/rig/RigSetupPage.cpp" line="233"/>
        <source>Camera (*.json)</source>
        <translation>攝影機 (*.json)</translation>
    </message>
    <message>
        <location filename="../app/rig/RigSetupPage.cpp" line="109"/>
        <location filename="../app/rig/RigSetupPage.cpp" line="115"/>
        <location filename="../app/rig/RigSetupPage.cpp" line="258"/>
        <location filename="../app/rig/RigSetupPage.cpp" line="263"/>
        <location filename="../app/rig/RigSetupPage.cpp" line="267"/>
        <location filename="../app/rig/RigSetupPage.cpp" line="275"/>
        <location filename="../app/rig/RigSetupPage.cpp" line="281"/>
        <source>Latency</source>
        <translation>延遲</translation>
    </message>
    <message>
        <location filename="../app/rig/RigSetupPage.cpp" line="110"/>
        <source>Loop latency: not measured (%1)</source>
        <translation>迴路延遲：未量度（%1）</translation>
    </message>
    <message>
        <location filename="../app/rig/RigSetupPage.cpp" line="116"/>
        <source>Loop latency: %1 ms (median of %2 steps, from %3 to %4 ms, std %5 ms); the trials compensate it</source>
        <translation>迴路延遲：%1 毫秒（%2 次階躍的中位數，由 %3 至 %4 毫秒，標準差 %5 毫秒）；試驗會補償此延遲</translation>
    </message>
    <message>
        <location filename="../app/rig/RigSetupPage.cpp" line="135"/>
        <source>The trial&apos;s bundle could not be written: %1</source>
        <translation>無法寫入試驗包：%1</translation>
    </message>
    <message>
        <location filename="../app/rig/RigSetupPage.cpp" line="215"/>
        <location filename="../app/rig/RigSetupPage.cpp" line="226"/>
        <location filename="../app/rig/RigSetupPage.cpp" line="253"/>
        <source>Lens</source>
        <translation>鏡頭</translation>
    </message>
    <message>
        <location filename="../app/rig/RigSetupPage.cpp" line="233"/>
        <location filename="../app/rig/RigSetupPage.cpp" line="236"/>
        <source>Save camera intrinsics</source>
        <translation>儲存攝影機內參</translation>
    </message>
    <message>
        <location filename="../app/rig/RigSetupPage.cpp" line="263"/>
        <source>Loop latency: %1</source>
        <translation>迴路延遲：%1</translation>
    </message>
    <message>
        <location filename="../app/rig/RigSetupPage.cpp" line="268"/>
        <source>Loop latency: measuring (keep the car at rest in view)...</source>
        <translation>迴路延遲：量度中（讓車輛靜止於視野內）...</translation>
    </message>
    <message>
        <location filename="../app/rig/RigSetupPage.cpp" line="276"/>
        <source>Loop latency: %1 ms, declared; the trials compensate it.</source>
        <translation>迴路延遲：%1 毫秒（已申報）；試驗會補償它。</translation>
    </message>
    <message>
        <location filename="../app/rig/RigSetupPage.cpp" line="282"/>
        <source>Loop latency: not declared any more (the controllers assume the profile&apos;s camera latency).</source>
        <translation>迴路延遲：已取消申報（控制器假設設定檔中的攝影機延遲）。</translation>
    </message>
    <message>
        <location filename="../app/rig/RigSetupPage.cpp" line="321"/>
        <source>Fence</source>
        <translation>圍欄</translation>
    </message>
    <message>
        <location filename="../app/rig/RigSetupPage.cpp" line="340"/>
        <source>Capture board view</source>
        <translation>擷取棋盤視圖</translation>
    </message>
    <message>
        <location filename="../app/rig/RigSetupPage.cpp" line="342"/>
        <source>Find the 9 x 6 chessboard (40 mm squares) in the camera&apos;s image and keep its corners; capture views over the whole image, tilted, its corners too</source>
        <translation>在攝影機影像中找出 9 x 6 棋盤（40 毫米方格）並保留其角點；在整個影像範圍（包括四角）以傾斜角度擷取多個視圖</translation>
    </message>
    <message>
        <location filename="../app/rig/RigSetupPage.cpp" line="345"/>
        <source>Fit lens</source>
        <translation>擬合鏡頭</translation>
    </message>
    <message>
        <location filename="../app/rig/RigSetupPage.cpp" line="347"/>
        <source>Fit the camera&apos;s intrinsics and distortion to the views captured; the floor calibration is fitted again through them</source>
        <translation>以擷取的視圖擬合攝影機內參及畸變；地面校準會經其重新擬合</translation>
    </message>
    <message>
        <location filename="../app/rig/RigSetupPage.cpp" line="349"/>
        <source>Load lens...</source>
        <translation>載入鏡頭...</translation>
    </message>
    <message>
        <location filename="../app/rig/RigSetupPage.cpp" line="350"/>
        <source>Camera intrinsics from a file (prisca-cli calibrate-camera)</source>
        <translation>從檔案載入攝影機內參（prisca-cli calibrate-camera）</translation>
    </message>
    <message>
        <location filename="../app/rig/RigSetupPage.cpp" line="351"/>
        <source>Measure latency</source>
        <translation>量度延遲</translation>
    </message>
    <message>
        <location filename="../app/rig/RigSetupPage.cpp" line="353"/>
        <source>With the car at rest in view and the link connected: step the throttle forward and back and time the response in the camera</source>
        <translation>車輛靜止於視野內且連結已接通時：前後階躍油門，並在攝影機中計時其反應</translation>
    </message>
    <message>
        <location filename="../app/rig/RigSetupPage.cpp" line="356"/>
        <source>or declare:</source>
        <translation>或申報：</translation>
    </message>
    <message>
        <location filename="../app/rig/RigSetupPage.cpp" line="357"/>
        <source> ms</source>
        <translation> 毫秒</translation>
    </message>
    <message>
        <location filename="../app/rig/RigSetupPage.cpp" line="358"/>
        <source>not declared</source>
        <translation>未申報</translation>
    </message>
    <message>
        <location filename="../app/rig/RigSetupPage.cpp" line="360"/>
        <source>A latency measured elsewhere [ms], for the trials to compensate; 0: not declared</source>
        <translation>在別處量得的延遲 [毫秒]，供試驗補償；0：未申報</translation>
    </message>
    <message>
        <location filename="../app/rig/RigSetupPage.cpp" line="362"/>
        <source>Draw fence</source>
        <translation>繪畫圍欄</translation>
    </message>
    <message>
        <location filename="../app/rig/RigSetupPage.cpp" line="363"/>
        <source>Clear fence</source>
        <translation>清除圍欄</translation>
    </message>
    <message>
        <location filename="../app/rig/RigSetupPage.cpp" line="364"/>
        <source>Speed limit:</source>
        <translation>速度上限：</translation>
    </message>
    <message>
        <location filename="../app/rig/RigSetupPage.cpp" line="365"/>
        <location filename="../app/rig/RigSetupPage.cpp" line="367"/>
        <source>none</source>
        <translation>無</translation>
    </message>
    <message>
        <location filename="../app/rig/RigSetupPage.cpp" line="366"/>
        <source>Longest lost track:</source>
        <translation>最長失去追蹤：</translation>
    </message>
    <message>
        <location filename="../app/rig/RigSetupPage.cpp" line="369"/>
        <source>Save every trial as a bundle</source>
        <translation>把每次試驗儲存為試驗包</translation>
    </message>
    <message>
        <location filename="../app/rig/RigSetupPage.cpp" line="370"/>
        <source>Poses, commands and 10 camera frames a second, in %1; File &gt; Replay a trial bundle opens one</source>
        <translation>位姿、指令及每秒 10 個攝影機影格，存於 %1；「檔案 &gt; 重播試驗包」可開啟</translation>
    </message>
    <message>
        <location filename="../app/rig/RigSetupPage.cpp" line="373"/>
        <source>Replay the last trial</source>
        <translation>重播上一次試驗</translation>
    </message>
    <message>
        <location filename="../app/rig/RigSetupPage.cpp" line="377"/>
        <source>Loop latency: not measured (the controllers assume the camera&apos;s latency).</source>
        <translation>迴路延遲：未量度（控制器假設攝影機的延遲）。</translation>
    </message>
</context>
<context>
    <name>prisca::app::RunPanel</name>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="184"/>
        <location filename="../app/panels/RunPanel.cpp" line="194"/>
        <source>Export run log</source>
        <translation>匯出運行記錄</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="185"/>
        <source>Run logs (*.csv)</source>
        <translation>運行記錄 (*.csv)</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="199"/>
        <source>Run log written to %1</source>
        <translation>運行記錄已寫入 %1</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="371"/>
        <source>No finished trial to write yet: run first.</source>
        <translation>尚未有完成的試驗可寫入：請先運行。</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="420"/>
        <source>Resume (F6)</source>
        <translation>繼續 (F6)</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="420"/>
        <source>Pause (F6)</source>
        <translation>暫停 (F6)</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="312"/>
        <source>The task changed: the previous results were cleared.</source>
        <translation>任務已改變：先前的結果已清除。</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="212"/>
        <source>the Run menu</source>
        <translation>「運行」選單</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="243"/>
        <source>Training before the run: %1 of %2...</source>
        <translation>運行前訓練：%1 / %2……</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="244"/>
        <location filename="../app/panels/RunPanel.cpp" line="409"/>
        <source>Training before the run...</source>
        <translation>運行前訓練中...</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="293"/>
        <source>E-STOP pressed at %1 (%2): nothing runs until Reset E-STOP.</source>
        <translation>%1 按下緊急停止（%2）：按「重設緊急停止」前不會運行任何工作。</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="299"/>
        <source>E-STOP was pressed at %1; it is reset now: ready to run.</source>
        <translation>緊急停止曾於 %1 按下；現已重設：可以運行。</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="414"/>
        <source>Run stopped.</source>
        <translation>運行已停止。</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="422"/>
        <source>Reset (Ctrl+R)</source>
        <translation>重設 (Ctrl+R)</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="439"/>
        <source>Stopped after %1 s: not a finished trial</source>
        <translation>在 %1 秒後停止：並非完成的試驗</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="446"/>
        <source>%1 (E-STOP)</source>
        <translation>%1（緊急停止）</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="447"/>
        <source>%1 (stopped)</source>
        <translation>%1（已停止）</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="470"/>
        <source> (cut short by E-STOP)</source>
        <translation>（被緊急停止中斷）</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="479"/>
        <source>Trial %1 diverged: its tracking error is %2 times the first trial&apos;s. The learner may have gone unstable; stop the run, or start learning again from the start.</source>
        <translation>第 %1 次試驗發散：其追蹤誤差是第一次試驗的 %2 倍。學習可能已變得不穩定；請停止運行，或由頭再開始學習。</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="514"/>
        <source>Trials in a row:</source>
        <translation>連續試驗次數：</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="515"/>
        <source>Learners keep what they learnt from one trial to the next.</source>
        <translation>學習方法會把一次試驗學到的保留到下一次。</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="516"/>
        <source>Seed:</source>
        <translation>隨機種子：</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="518"/>
        <source>Draws the perturbation and sensor noise of each trial; the same seed gives the same trials.</source>
        <translation>決定每次試驗的擾動與感測器噪聲；相同種子產生相同試驗。</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="520"/>
        <source>Perturbation:</source>
        <translation>擾動：</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="522"/>
        <source>Start offsets, friction and gain variation, trim and actuator noise: 0 nominal, 1 a realistic lab.</source>
        <translation>起始偏移、摩擦與增益變化、微調偏差及致動器噪聲：0 為標稱，1 為真實實驗室水平。</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="524"/>
        <source>Sensor noise:</source>
        <translation>感測器噪聲：</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="526"/>
        <source>Measurement noise, latency and dropped samples: 0 perfect, 1 realistic.</source>
        <translation>量測噪聲、延遲及丟失樣本：0 為完美，1 為真實水平。</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="528"/>
        <source>Speed:</source>
        <translation>速度：</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="529"/>
        <source>Real time (1x)</source>
        <translation>實時 (1x)</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="530"/>
        <source>10x</source>
        <translation>10 倍</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="531"/>
        <source>As fast as possible</source>
        <translation>盡快</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="541"/>
        <source>Stops the run, a recording and the rig at once (within one control period) and stays engaged until reset. Space outside text fields, or Esc.</source>
        <translation>立即停止運行、錄製及實機（在一個控制週期內），並保持啟動直至重設。在文字欄以外按空格鍵，或按 Esc。</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="419"/>
        <source>Run (F5)</source>
        <translation>運行 (F5)</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="198"/>
        <location filename="../app/panels/RunPanel.cpp" line="250"/>
        <location filename="../app/panels/RunPanel.cpp" line="292"/>
        <location filename="../app/panels/RunPanel.cpp" line="298"/>
        <location filename="../app/panels/RunPanel.cpp" line="311"/>
        <location filename="../app/panels/RunPanel.cpp" line="322"/>
        <location filename="../app/panels/RunPanel.cpp" line="358"/>
        <location filename="../app/panels/RunPanel.cpp" line="406"/>
        <location filename="../app/panels/RunPanel.cpp" line="409"/>
        <location filename="../app/panels/RunPanel.cpp" line="414"/>
        <location filename="../app/panels/RunPanel.cpp" line="455"/>
        <source>Run</source>
        <translation>運行</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="234"/>
        <source>Trial 1 of %1 running...</source>
        <translation>正在進行第 1 次試驗（共 %1 次）……</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="235"/>
        <source>Trial %1 of %2 running · %3</source>
        <translation>正在進行第 %1 次試驗（共 %2 次）· %3</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="251"/>
        <source>Run finished: 1 trial.</source>
        <translation>運行完成：1 次試驗。</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="252"/>
        <source>Run finished: %1 trials.</source>
        <translation>運行完成：%1 次試驗。</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="359"/>
        <source>Run started: %1, %2 trial(s), seed %3, perturbation %4, sensor noise %5</source>
        <translation>運行開始：%1，%2 次試驗，種子 %3，擾動 %4，感測器雜訊 %5</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="407"/>
        <source>Identifying the car&apos;s model before the run...</source>
        <translation>運行前識別車輛模型中...</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="421"/>
        <source>Stop (Shift+F5)</source>
        <translation>停止 (Shift+F5)</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="453"/>
        <source>tracking RMS %1 m</source>
        <translation>追蹤 RMS %1 m</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="456"/>
        <source>Trial %1: parked %2 cm and %3 deg off; %4</source>
        <translation>試驗 %1：泊車偏差 %2 cm 及 %3 度；%4</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="461"/>
        <source>Trial %1: %2</source>
        <translation>試驗 %1：%2</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="464"/>
        <source>; ran out %1 s in neutral, scored where it rests</source>
        <translation>；油門回中後滑行 %1 秒，以停定的位置計分</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="471"/>
        <source> (stopped part-way)</source>
        <translation>（中途停止）</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="533"/>
        <source>Export run log...</source>
        <translation>匯出運行記錄...</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="535"/>
        <source>Every control step of the last run&apos;s finished trials, in the format of prisca-cli run --out (state, observation, reference, error, u, u*, cost, θ)</source>
        <translation>上次運行中已完成試驗的每一個控制步，格式與 prisca-cli run --out 相同（狀態、觀測、參考、誤差、u、u*、成本、θ）</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="538"/>
        <source>Stop the run and clear the trails, charts and results (Ctrl+R)</source>
        <translation>停止運行並清除軌跡、圖表和結果 (Ctrl+R)</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="539"/>
        <source>E-STOP (Space / Esc)</source>
        <translation>緊急停止（空格鍵 / Esc）</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="543"/>
        <source>Reset E-STOP</source>
        <translation>重設緊急停止</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="544"/>
        <source>Stop the run</source>
        <translation>停止運行</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="545"/>
        <source>Start learning again</source>
        <translation>重新開始學習</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="547"/>
        <source>Stop this run and start a new one: the method starts again from its initial policy</source>
        <translation>停止本次運行並開始新的一次：方法由其初始策略重新開始</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="548"/>
        <source>Release the E-STOP latch so a run can start again</source>
        <translation>解除緊急停止鎖定，以便再次開始運行</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="551"/>
        <source>Trial</source>
        <translation>試驗</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="551"/>
        <source>Δp [cm]</source>
        <translation>Δp [厘米]</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="551"/>
        <source>Δψ [deg]</source>
        <translation>Δψ [度]</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="552"/>
        <source>RMS [m]</source>
        <translation>RMS [米]</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="552"/>
        <source>RMS [rad]</source>
        <translation>RMS [弧度]</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="554"/>
        <source>Trial in the run</source>
        <translation>本次運行中的試驗</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="554"/>
        <source>Final position error: distance from the lot [cm]</source>
        <translation>最終位置誤差：與泊車位的距離 [厘米]</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="555"/>
        <source>Final heading error [deg]</source>
        <translation>最終航向誤差 [度]</translation>
    </message>
    <message>
        <location filename="../app/panels/RunPanel.cpp" line="555"/>
        <source>Time-aligned RMS tracking error over the trial</source>
        <translation>整次試驗按時間對齊的均方根追蹤誤差</translation>
    </message>
</context>
<context>
    <name>prisca::app::RunWorker</name>
    <message>
        <location filename="../app/workers/RunWorker.cpp" line="46"/>
        <source>E-STOP is engaged: reset it before starting a run.</source>
        <translation>緊急停止已啟動：開始運行前請先重設。</translation>
    </message>
    <message>
        <location filename="../app/workers/RunWorker.cpp" line="81"/>
        <source>Cannot start the run: %1</source>
        <translation>無法開始運行：%1</translation>
    </message>
    <message>
        <location filename="../app/workers/RunWorker.cpp" line="95"/>
        <source>Trial %1 of %2</source>
        <translation>第 %1 次試驗（共 %2 次）</translation>
    </message>
    <message>
        <location filename="../app/workers/RunWorker.cpp" line="174"/>
        <source>Run finished: %1 trials</source>
        <translation>運行完成：%1 次試驗</translation>
    </message>
    <message>
        <location filename="../app/workers/RunWorker.cpp" line="223"/>
        <source>The trial&apos;s bundle could not be written: %1</source>
        <translation>無法寫入試驗包：%1</translation>
    </message>
    <message>
        <location filename="../app/workers/RunWorker.cpp" line="248"/>
        <source>Run stopped</source>
        <translation>運行已停止</translation>
    </message>
    <message>
        <location filename="../app/workers/RunWorker.cpp" line="266"/>
        <source>E-STOP: run stopped</source>
        <translation>緊急停止：運行已停止</translation>
    </message>
</context>
<context>
    <name>prisca::app::TaskPanel</name>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="182"/>
        <location filename="../app/panels/TaskPanel.cpp" line="189"/>
        <location filename="../app/panels/TaskPanel.cpp" line="242"/>
        <source>Open demonstration</source>
        <translation>開啟示範</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="183"/>
        <source>The demonstration could not be read.

%1</source>
        <translation>無法讀取示範。

%1</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="190"/>
        <location filename="../app/panels/TaskPanel.cpp" line="210"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="243"/>
        <source>Demonstrations (*.csv);;All files (*)</source>
        <translation>示範 (*.csv);;所有檔案 (*)</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="251"/>
        <location filename="../app/panels/TaskPanel.cpp" line="258"/>
        <source>Save demonstration</source>
        <translation>儲存示範</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="252"/>
        <source>Demonstrations (*.csv)</source>
        <translation>示範 (*.csv)</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="174"/>
        <source>Scripted demonstration</source>
        <translation>腳本示範</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="121"/>
        <source>figure-eight</source>
        <translation>8 字形</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="121"/>
        <source>s-turn</source>
        <translation>S 形轉彎</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="122"/>
        <source>u-turn</source>
        <translation>掉頭</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="122"/>
        <source>s-bend</source>
        <translation>S 形彎</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="124"/>
        <source>stick</source>
        <translation>搖桿</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="124"/>
        <source>keyboard</source>
        <translation>鍵盤</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="124"/>
        <source>standstill</source>
        <translation>靜止起步</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="124"/>
        <source>fast</source>
        <translation>快速</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="125"/>
        <source>slow</source>
        <translation>慢速</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="125"/>
        <source>blip</source>
        <translation>點油</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="125"/>
        <source>jitter</source>
        <translation>抖動</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="125"/>
        <source>coast</source>
        <translation>滑行</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="126"/>
        <source>left</source>
        <translation>左</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="126"/>
        <source>right</source>
        <translation>右</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="126"/>
        <source>swing</source>
        <translation>擺動</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="126"/>
        <source>medium</source>
        <translation>中</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="127"/>
        <source>small</source>
        <translation>小</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="127"/>
        <source>large</source>
        <translation>大</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="127"/>
        <source>circle</source>
        <translation>圓形</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="127"/>
        <source>wide</source>
        <translation>寬</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="128"/>
        <source>dock</source>
        <translation>泊位</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="128"/>
        <source>spin</source>
        <translation>原地轉</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="146"/>
        <source>%1°</source>
        <translation>%1°</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="201"/>
        <location filename="../app/panels/TaskPanel.cpp" line="209"/>
        <location filename="../app/panels/TaskPanel.cpp" line="219"/>
        <source>Open plant file</source>
        <translation>開啟機型檔</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="202"/>
        <source>The plant file could not be used.

%1</source>
        <translation>無法使用此機型檔。

%1</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="220"/>
        <source>Plant files (*.json);;All files (*)</source>
        <translation>機型檔 (*.json);;所有檔案 (*)</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="230"/>
        <source>the catalog&apos;s</source>
        <translation>目錄預設</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="271"/>
        <source>the scripted operator (%1, seed %2)</source>
        <translation>腳本操作員（%1，種子 %2）</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="275"/>
        <source>Demonstration: %1 samples, %2 s at %3 Hz, from %4.</source>
        <translation>示範：%1 個樣本，%2 秒，%3 Hz，來自%4。</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="290"/>
        <source>Target:</source>
        <translation>對象：</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="301"/>
        <source>Open...</source>
        <translation>開啟...</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="302"/>
        <source>Open a demonstration CSV recorded earlier</source>
        <translation>開啟先前錄製的示範 CSV</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="303"/>
        <source>Save as...</source>
        <translation>另存為...</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="304"/>
        <source>Save the demonstration as CSV</source>
        <translation>把示範儲存為 CSV</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="305"/>
        <source>Scripted operator:</source>
        <translation>腳本操作員：</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="307"/>
        <source>How the scripted operator demonstrates: keys or stick, left or right, how far and how fast (hover over a style for its description)</source>
        <translation>腳本操作員如何示範：按鍵或搖桿、向左或向右、轉多少、多快（將滑鼠停在風格上可看說明）</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="309"/>
        <source>Seed of the operator&apos;s hand variation</source>
        <translation>操作員手部變化的種子</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="310"/>
        <source>seed </source>
        <translation>種子 </translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="311"/>
        <source>Physical parameters:</source>
        <translation>物理參數：</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="312"/>
        <source>Load...</source>
        <translation>載入...</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="314"/>
        <source>Load a plant file: the car&apos;s mass, wheelbase, grip, motor, steering and servo (prisca-cli plant --plant NAME --print-params --format json writes one to edit)</source>
        <translation>載入機型檔：車的質量、軸距、抓地力、馬達、轉向及伺服器（prisca-cli plant --plant NAME --print-params --format json 可寫出一份供編輯）</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="316"/>
        <source>Catalog</source>
        <translation>目錄預設</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="317"/>
        <source>Go back to the catalog&apos;s plant</source>
        <translation>回到目錄預設的機型</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="319"/>
        <source>Use scripted</source>
        <translation>使用腳本</translation>
    </message>
    <message>
        <location filename="../app/panels/TaskPanel.cpp" line="321"/>
        <source>Use the scripted operator&apos;s demonstration in the chosen style and seed</source>
        <translation>使用所選風格與種子的腳本操作員示範</translation>
    </message>
</context>
<context>
    <name>prisca::devices::TransmitterLink</name>
    <message>
        <location filename="../devices/TransmitterLink.cpp" line="40"/>
        <source>none</source>
        <translation>無</translation>
    </message>
    <message>
        <location filename="../devices/TransmitterLink.cpp" line="42"/>
        <source>no command yet</source>
        <translation>尚未有指令</translation>
    </message>
    <message>
        <location filename="../devices/TransmitterLink.cpp" line="45"/>
        <source>stale command</source>
        <translation>指令過時</translation>
    </message>
    <message>
        <location filename="../devices/TransmitterLink.cpp" line="47"/>
        <source>E-STOP</source>
        <translation>緊急停止</translation>
    </message>
    <message>
        <location filename="../devices/TransmitterLink.cpp" line="49"/>
        <source>camera pose lost</source>
        <translation>失去鏡頭位姿</translation>
    </message>
    <message>
        <location filename="../devices/TransmitterLink.cpp" line="52"/>
        <source>controller fault</source>
        <translation>控制器故障</translation>
    </message>
    <message>
        <location filename="../devices/TransmitterLink.cpp" line="55"/>
        <source>fence breached</source>
        <translation>越過圍欄</translation>
    </message>
</context>
<context>
    <name>prisca::rig::PreTrialCheck</name>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="40"/>
        <source>Latency</source>
        <translation>延遲</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="43"/>
        <source>measured: %1 ms</source>
        <translation>已量度：%1 毫秒</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="47"/>
        <source>declared: %1 ms</source>
        <translation>已申報：%1 毫秒</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="51"/>
        <source>the virtual camera&apos;s, known (the profile&apos;s assumption)</source>
        <translation>虛擬攝影機的延遲，已知（設定檔的假設）</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="54"/>
        <source>The loop&apos;s latency is neither measured nor declared: measure it (the car at rest in view) or declare the value measured elsewhere.</source>
        <translation>迴路延遲既未量度也未申報：請量度（車靜止在畫面內），或申報在別處量得的數值。</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="59"/>
        <source>Fence</source>
        <translation>圍欄</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="63"/>
        <source>No fence: a car that runs away is stopped only by E-STOP and the lost-track guard. Draw one (the Rig tab&apos;s set-up page; prisca-cli rig --fence).</source>
        <translation>沒有圍欄：失控的車只能靠緊急停止和失追蹤保護停下。請畫一個（「實機」分頁的設定頁；prisca-cli rig --fence）。</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="79"/>
        <source>The lot %1 is outside the fence: the trial would end in failsafe. Move the fence or record the demonstration inside it.</source>
        <translation>泊車位 %1 在圍欄外：試驗會以失效保護結束。請移動圍欄，或在圍欄內錄製示範。</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="85"/>
        <source>%1 of the demonstration&apos;s %2 points are outside the fence (the first at %3): the trial would end in failsafe.</source>
        <translation>示範的 %2 個點中有 %1 個在圍欄外（第一個在 %3）：試驗會以失效保護結束。</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="91"/>
        <source>the path and the lot are inside it</source>
        <translation>路徑和泊車位都在圍欄內</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="95"/>
        <source>In view</source>
        <translation>在畫面內</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="99"/>
        <source>No frame yet: the path cannot be checked against the camera&apos;s view.</source>
        <translation>尚未有畫面：無法核對路徑是否在攝影機視野內。</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="125"/>
        <source>The lot %1 is outside the camera&apos;s view: the car would be lost where it should park. Record the demonstration in view, or move the camera and calibrate again.</source>
        <translation>泊車位 %1 在攝影機視野外：車在應泊車處會失去追蹤。請在視野內錄製示範，或移動攝影機後重新校準。</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="132"/>
        <source>%1 of the demonstration&apos;s %2 points are outside the camera&apos;s view (the first at %3).</source>
        <translation>示範的 %2 個點中有 %1 個在攝影機視野外（第一個在 %3）。</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="138"/>
        <source>the path and the lot are in view</source>
        <translation>路徑和泊車位都在畫面內</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="203"/>
        <location filename="../rig/PreTrialCheck.cpp" line="204"/>
        <source>Camera</source>
        <translation>攝影機</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="203"/>
        <source>running</source>
        <translation>運行中</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="205"/>
        <source>Start the camera first.</source>
        <translation>請先啟動攝影機。</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="206"/>
        <location filename="../rig/PreTrialCheck.cpp" line="210"/>
        <source>Car</source>
        <translation>車</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="207"/>
        <source>the virtual car, put at the start by each trial</source>
        <translation>虛擬車，每次試驗放回起點</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="209"/>
        <source>in view</source>
        <translation>在畫面內</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="211"/>
        <source>The camera does not see the car: put it in view with its LEDs on.</source>
        <translation>攝影機看不到車：請把車放在畫面內並開啟其 LED。</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="216"/>
        <location filename="../rig/PreTrialCheck.cpp" line="218"/>
        <location filename="../rig/PreTrialCheck.cpp" line="222"/>
        <location filename="../rig/PreTrialCheck.cpp" line="224"/>
        <source>Calibration</source>
        <translation>校準</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="216"/>
        <source>the virtual camera&apos;s</source>
        <translation>虛擬攝影機的校準</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="219"/>
        <source>The floor calibration is the virtual rig&apos;s, not this camera&apos;s: calibrate this camera or open its calibration.</source>
        <translation>地面校準屬於虛擬實機，不屬於此攝影機：請校準此攝影機或打開其校準檔。</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="225"/>
        <source>%1 points, RMS %2 mm</source>
        <translation>%1 個點，均方根 %2 毫米</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="230"/>
        <location filename="../rig/PreTrialCheck.cpp" line="232"/>
        <location filename="../rig/PreTrialCheck.cpp" line="237"/>
        <source>Lens</source>
        <translation>鏡頭</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="230"/>
        <source>none needed (virtual)</source>
        <translation>毋須（虛擬）</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="233"/>
        <source>fx %1 px, k1 %2</source>
        <translation>fx %1 像素，k1 %2</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="238"/>
        <source>No lens: fit the camera&apos;s intrinsics from board views or open them (a wide lens bends the floor by centimetres at the edges).</source>
        <translation>沒有鏡頭參數：請由棋盤視圖擬合攝影機內參或打開內參檔（廣角鏡頭在邊緣會令地面偏差數厘米）。</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="244"/>
        <location filename="../rig/PreTrialCheck.cpp" line="246"/>
        <location filename="../rig/PreTrialCheck.cpp" line="249"/>
        <source>Link</source>
        <translation>鏈路</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="244"/>
        <source>Connect the transmitter link first.</source>
        <translation>請先連接發射器鏈路。</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="247"/>
        <source>The link reports an error: %1</source>
        <translation>鏈路報告錯誤：%1</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="249"/>
        <source>connected</source>
        <translation>已連接</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="254"/>
        <location filename="../rig/PreTrialCheck.cpp" line="255"/>
        <source>E-STOP</source>
        <translation>緊急停止</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="182"/>
        <source>E-STOP is latched: reset it before a trial.</source>
        <translation>緊急停止已鎖定：試驗前請重設。</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="255"/>
        <source>ready</source>
        <translation>就緒</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="260"/>
        <source>The rig needs a demonstration of a planar vehicle.</source>
        <translation>實機需要平面車輛的示範。</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="262"/>
        <source>The rig drives a slide-car: choose the slide-car as the target.</source>
        <translation>實機駕駛的是漂移車：請選擇漂移車作為目標。</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="187"/>
        <source>The oracle plans on copies of a simulated plant; a real car has none. Run it in simulation, or choose another method.</source>
        <translation>預言者在模擬對象的副本上規劃；真車沒有副本。請在模擬中運行，或選擇其他方法。</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="178"/>
        <source>The program was stopped and continued; the car went without commands meanwhile, so the link holds failsafe: reset E-STOP to release it.</source>
        <translation>程式曾被暫停後再繼續；其間車輛沒有收到指令，因此連線維持在安全狀態：請重設緊急停止以解除。</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="192"/>
        <source>%1 trains offline in simulation; run it there, or choose another method.</source>
        <translation>%1 在模擬中離線訓練；請在模擬中運行，或選擇其他方法。</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="268"/>
        <source>%1 plans through the car&apos;s model, and none is identified yet: identify the car first (the Model tab; prisca-cli identify, then --model).</source>
        <translation>%1 須經車輛的模型規劃，但尚未辨識任何模型：請先辨識車輛（「模型」分頁；或 prisca-cli identify，再加 --model）。</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="273"/>
        <location filename="../rig/PreTrialCheck.cpp" line="275"/>
        <source>Task</source>
        <translation>任務</translation>
    </message>
    <message>
        <location filename="../rig/PreTrialCheck.cpp" line="274"/>
        <source>%1 on the slide-car</source>
        <translation>%1 駕駛漂移車</translation>
    </message>
</context>
<context>
    <name>prisca::rig::RigCalibration</name>
    <message>
        <location filename="../rig/RigCalibration.cpp" line="19"/>
        <source>%1 point(s) clicked; at least 4 are needed.</source>
        <translation>已點擊 %1 個點；至少需要 4 個。</translation>
    </message>
    <message>
        <location filename="../rig/RigCalibration.cpp" line="38"/>
        <source>&apos;%1&apos; is not two numbers &quot;x, y&quot; in metres.</source>
        <translation>「%1」不是兩個以米為單位的數字「x, y」。</translation>
    </message>
    <message>
        <location filename="../rig/RigCalibration.cpp" line="48"/>
        <source>The calibration could not be read.

%1</source>
        <translation>無法讀取校準。

%1</translation>
    </message>
    <message>
        <location filename="../rig/RigCalibration.cpp" line="63"/>
        <source>Floor calibration: %1 points, reprojection error %2 cm</source>
        <translation>地面校準：%1 個點，重投影誤差 %2 厘米</translation>
    </message>
    <message>
        <location filename="../rig/RigCalibration.cpp" line="75"/>
        <source>The floor calibration is the virtual rig&apos;s, not this camera&apos;s: calibrate this camera (Calibrate, then click four or more floor points) or open its calibration before driving or a trial.</source>
        <translation>地面校準屬於虛擬實驗台，而非此攝影機：駕駛或試驗前，請校準此攝影機（按「校準」，再點選四個或以上地面點）或開啟其校準檔。</translation>
    </message>
    <message>
        <location filename="../rig/RigCalibration.cpp" line="83"/>
        <source>Lens: no camera image to capture a board view from.</source>
        <translation>鏡頭：沒有可擷取棋盤視圖的攝影機影像。</translation>
    </message>
    <message>
        <location filename="../rig/RigCalibration.cpp" line="87"/>
        <source>Lens: no whole 9 x 6 board in this view (%1 captured). Hold the board so all of it is seen, still, and try again.</source>
        <translation>鏡頭：此視圖中沒有完整的 9 x 6 棋盤（已擷取 %1 個）。請拿穩棋盤，使其完全可見，然後再試。</translation>
    </message>
    <message>
        <location filename="../rig/RigCalibration.cpp" line="110"/>
        <source>refused: %1</source>
        <translation>已拒絕：%1</translation>
    </message>
    <message>
        <location filename="../rig/RigCalibration.cpp" line="115"/>
        <source>Lens: %1</source>
        <translation>鏡頭：%1</translation>
    </message>
    <message>
        <location filename="../rig/RigCalibration.cpp" line="137"/>
        <source>No lens has been fitted or opened.</source>
        <translation>尚未擬合或開啟鏡頭。</translation>
    </message>
    <message>
        <location filename="../rig/RigCalibration.cpp" line="157"/>
        <source>Lens: fx %1 px, k1 %2, k2 %3; RMS %4 px.</source>
        <translation>鏡頭：fx %1 像素，k1 %2，k2 %3；均方根 %4 像素。</translation>
    </message>
    <message>
        <location filename="../rig/RigCalibration.cpp" line="163"/>
        <source>Lens: none (the floor calibration is a homography alone).</source>
        <translation>鏡頭：無（地面校準只是單應性變換）。</translation>
    </message>
    <message>
        <location filename="../rig/RigCalibration.cpp" line="167"/>
        <source>%1 board view(s) captured (at least %2; move the board over the whole image, its corners too).</source>
        <translation>已擷取 %1 個棋盤視圖（至少需要 %2 個；把棋盤移遍整個影像，包括四角）。</translation>
    </message>
    <message>
        <location filename="../rig/RigCalibration.cpp" line="230"/>
        <source>Fence: %1</source>
        <translation>圍欄：%1</translation>
    </message>
    <message>
        <location filename="../rig/RigCalibration.cpp" line="233"/>
        <source>Fence: %1 corners; a car outside it ends the trial in failsafe.</source>
        <translation>圍欄：%1 個角；車輛離開圍欄時試驗以失效保護結束。</translation>
    </message>
    <message>
        <location filename="../rig/RigCalibration.cpp" line="237"/>
        <source>Fence: none (%1 corner(s) clicked; 3 or more make one).</source>
        <translation>圍欄：無（已點擊 %1 個角；需 3 個或以上）。</translation>
    </message>
</context>
<context>
    <name>prisca::rig::RigDoctor</name>
    <message>
        <location filename="../rig/RigDoctor.cpp" line="22"/>
        <source>%1 GiB</source>
        <translation>%1 GiB</translation>
    </message>
    <message>
        <location filename="../rig/RigDoctor.cpp" line="23"/>
        <source>%1 MiB</source>
        <translation>%1 MiB</translation>
    </message>
    <message>
        <location filename="../rig/RigDoctor.cpp" line="35"/>
        <source>not there (%1)</source>
        <translation>不存在（%1）</translation>
    </message>
    <message>
        <location filename="../rig/RigDoctor.cpp" line="41"/>
        <source>cannot be opened (%1)</source>
        <translation>無法開啟（%1）</translation>
    </message>
    <message>
        <location filename="../rig/RigDoctor.cpp" line="44"/>
        <source>cannot be opened: you were added to the group %1 but have not logged in since; log out and in again</source>
        <translation>無法開啟：你已加入群組 %1，但之後尚未重新登入；請登出再登入</translation>
    </message>
    <message>
        <location filename="../rig/RigDoctor.cpp" line="49"/>
        <source>cannot be opened: it belongs to the group %1, which you are not in; run sudo usermod -aG %1 $USER and log in again</source>
        <translation>無法開啟：它屬於群組 %1，而你不在該群組；請執行 sudo usermod -aG %1 $USER，然後重新登入</translation>
    </message>
    <message>
        <location filename="../rig/RigDoctor.cpp" line="85"/>
        <source>Serial port %1</source>
        <translation>序列埠 %1</translation>
    </message>
    <message>
        <location filename="../rig/RigDoctor.cpp" line="86"/>
        <source>can be opened%1</source>
        <translation>可以開啟%1</translation>
    </message>
    <message>
        <location filename="../rig/RigDoctor.cpp" line="92"/>
        <source>Transmitter link</source>
        <translation>發射器鏈路</translation>
    </message>
    <message>
        <location filename="../rig/RigDoctor.cpp" line="93"/>
        <source>a serial port this user can open</source>
        <translation>有此用戶可開啟的序列埠</translation>
    </message>
    <message>
        <location filename="../rig/RigDoctor.cpp" line="94"/>
        <source>no USB serial adapter found: plug in the transmitter&apos;s USB-serial adapter or the bridge board (the kernel&apos;s log, dmesg, says what it saw)</source>
        <translation>找不到 USB 序列轉接器：請插上發射器的 USB 序列轉接器或橋接板（核心日誌 dmesg 會列出所見裝置）</translation>
    </message>
    <message>
        <location filename="../rig/RigDoctor.cpp" line="97"/>
        <source>no serial port this user can open: see the ports above</source>
        <translation>沒有此用戶可開啟的序列埠：見上面各埠</translation>
    </message>
    <message>
        <location filename="../rig/RigDoctor.cpp" line="103"/>
        <source>Serial adapter rule</source>
        <translation>序列轉接器規則</translation>
    </message>
    <message>
        <location filename="../rig/RigDoctor.cpp" line="105"/>
        <source>installed: %1</source>
        <translation>已安裝：%1</translation>
    </message>
    <message>
        <location filename="../rig/RigDoctor.cpp" line="106"/>
        <source>not installed: the package installs it; from a build, sudo cp packaging/70-prisca-lab.rules /etc/udev/rules.d/ (or join the group dialout)</source>
        <translation>未安裝：安裝套件時會一併安裝；由原始碼建置時，請執行 sudo cp packaging/70-prisca-lab.rules /etc/udev/rules.d/（或加入群組 dialout）</translation>
    </message>
    <message>
        <location filename="../rig/RigDoctor.cpp" line="127"/>
        <source>cannot be queried: %1</source>
        <translation>無法查詢：%1</translation>
    </message>
    <message>
        <location filename="../rig/RigDoctor.cpp" line="129"/>
        <source>%1: no video capture</source>
        <translation>%1：不能擷取影像</translation>
    </message>
    <message>
        <location filename="../rig/RigDoctor.cpp" line="131"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location filename="../rig/RigDoctor.cpp" line="132"/>
        <source>no modes listed</source>
        <translation>沒有列出模式</translation>
    </message>
    <message>
        <location filename="../rig/RigDoctor.cpp" line="136"/>
        <source>Camera %1</source>
        <translation>攝影機 %1</translation>
    </message>
    <message>
        <location filename="../rig/RigDoctor.cpp" line="140"/>
        <source>Camera</source>
        <translation>攝影機</translation>
    </message>
    <message>
        <location filename="../rig/RigDoctor.cpp" line="141"/>
        <source>a video capture device this user can open</source>
        <translation>有此用戶可開啟的影像擷取裝置</translation>
    </message>
    <message>
        <location filename="../rig/RigDoctor.cpp" line="143"/>
        <source>no camera found (/dev/video*): plug in the ceiling camera; the virtual rig needs none</source>
        <translation>找不到攝影機（/dev/video*）：請插上天花板攝影機；虛擬實機不需要攝影機</translation>
    </message>
    <message>
        <location filename="../rig/RigDoctor.cpp" line="146"/>
        <source>no camera this user can open: see the devices above</source>
        <translation>沒有此用戶可開啟的攝影機：見上面各裝置</translation>
    </message>
    <message>
        <location filename="../rig/RigDoctor.cpp" line="157"/>
        <source>%1 reads and is valid</source>
        <translation>%1 可讀取且有效</translation>
    </message>
    <message>
        <location filename="../rig/RigDoctor.cpp" line="159"/>
        <source>%1 was not read</source>
        <translation>未讀取 %1</translation>
    </message>
    <message>
        <location filename="../rig/RigDoctor.cpp" line="215"/>
        <source>Floor calibration</source>
        <translation>地面校準</translation>
    </message>
    <message>
        <location filename="../rig/RigDoctor.cpp" line="217"/>
        <source>Lens</source>
        <translation>鏡頭</translation>
    </message>
    <message>
        <location filename="../rig/RigDoctor.cpp" line="219"/>
        <source>Display</source>
        <translation>顯示器</translation>
    </message>
    <message>
        <location filename="../rig/RigDoctor.cpp" line="222"/>
        <source>none (DISPLAY and WAYLAND_DISPLAY unset): the window needs one; prisca-cli does not</source>
        <translation>無（未設定 DISPLAY 及 WAYLAND_DISPLAY）：視窗需要顯示器；prisca-cli 不需要</translation>
    </message>
    <message>
        <location filename="../rig/RigDoctor.cpp" line="226"/>
        <source>OpenGL</source>
        <translation>OpenGL</translation>
    </message>
    <message>
        <location filename="../rig/RigDoctor.cpp" line="229"/>
        <source>%1, a GPU render node</source>
        <translation>%1，有 GPU 渲染節點</translation>
    </message>
    <message>
        <location filename="../rig/RigDoctor.cpp" line="230"/>
        <source>%1, software rendering (no GPU render node)</source>
        <translation>%1，軟件渲染（沒有 GPU 渲染節點）</translation>
    </message>
    <message>
        <location filename="../rig/RigDoctor.cpp" line="232"/>
        <source>no OpenGL library: install libgl1 (the window&apos;s charts need it)</source>
        <translation>沒有 OpenGL 程式庫：請安裝 libgl1（視窗的圖表需要它）</translation>
    </message>
    <message>
        <location filename="../rig/RigDoctor.cpp" line="237"/>
        <source>cannot read the free space under %1</source>
        <translation>無法讀取 %1 的可用空間</translation>
    </message>
    <message>
        <location filename="../rig/RigDoctor.cpp" line="239"/>
        <source>%1 free under %2</source>
        <translation>%2 有 %1 可用空間</translation>
    </message>
    <message>
        <location filename="../rig/RigDoctor.cpp" line="242"/>
        <source>only %1 free under %2: a session&apos;s bundles need %3; free some space or choose another folder</source>
        <translation>%2 只有 %1 可用空間：一節工作的試驗包需要 %3；請騰出空間或選擇其他資料夾</translation>
    </message>
    <message>
        <location filename="../rig/RigDoctor.cpp" line="249"/>
        <source>Free space for trial bundles</source>
        <translation>試驗包的可用空間</translation>
    </message>
    <message>
        <location filename="../rig/RigDoctor.cpp" line="251"/>
        <source>Folders</source>
        <translation>資料夾</translation>
    </message>
    <message>
        <location filename="../rig/RigDoctor.cpp" line="252"/>
        <source>settings %1; recordings %2; trial bundles %3; cache %4</source>
        <translation>設定 %1；錄製 %2；試驗包 %3；快取 %4</translation>
    </message>
</context>
<context>
    <name>prisca::rig::RigSession</name>
    <message>
        <location filename="../rig/RigSession.cpp" line="94"/>
        <source>The virtual camera needs a frame rate above zero.</source>
        <translation>虛擬攝影機的影格率必須大於零。</translation>
    </message>
    <message>
        <location filename="../rig/RigSession.cpp" line="223"/>
        <source>Start the camera first.</source>
        <translation>請先啟動攝影機。</translation>
    </message>
    <message>
        <location filename="../rig/RigSession.cpp" line="226"/>
        <source>Connect the transmitter link first.</source>
        <translation>請先連接發射器。</translation>
    </message>
    <message>
        <location filename="../rig/RigSessionTrials.cpp" line="91"/>
        <source>Only the virtual rig&apos;s car can be put back; carry a real one.</source>
        <translation>只有虛擬實機的車可以自動放回；真車請用手搬回。</translation>
    </message>
    <message>
        <location filename="../rig/RigSessionTrials.cpp" line="97"/>
        <source>A trial is running: stop it first.</source>
        <translation>試驗正在進行：請先停止。</translation>
    </message>
    <message>
        <location filename="../rig/RigSessionTrials.cpp" line="119"/>
        <source>The rig needs a demonstration of a planar vehicle.</source>
        <translation>實驗台需要平面車輛的示範。</translation>
    </message>
    <message>
        <location filename="../rig/RigSessionTrials.cpp" line="128"/>
        <source>A trial is already running.</source>
        <translation>已有一次試驗正在進行。</translation>
    </message>
    <message>
        <location filename="../rig/RigSessionTrials.cpp" line="131"/>
        <source>The latency is being measured.</source>
        <translation>正在量度延遲。</translation>
    </message>
    <message>
        <location filename="../rig/RigSession.cpp" line="357"/>
        <location filename="../rig/RigSessionTrials.cpp" line="137"/>
        <source>Stop driving first.</source>
        <translation>請先停止駕駛。</translation>
    </message>
    <message>
        <location filename="../rig/RigSessionTrials.cpp" line="148"/>
        <location filename="../rig/RigSessionTrials.cpp" line="171"/>
        <source>%1 could not be set up: %2</source>
        <translation>無法設定 %1：%2</translation>
    </message>
    <message>
        <location filename="../rig/RigSessionTrials.cpp" line="422"/>
        <source>the process was stopped and continued: failsafe held</source>
        <translation>程式曾被暫停後再繼續：保持失效保護</translation>
    </message>
    <message>
        <location filename="../rig/RigSession.cpp" line="243"/>
        <source>The camera has not opened yet; try again in a moment.</source>
        <translation>攝影機尚未開啟，請稍後再試。</translation>
    </message>
    <message>
        <location filename="../rig/RigSession.cpp" line="246"/>
        <source>A trial or a recording is already running.</source>
        <translation>已有試驗或錄製正在進行。</translation>
    </message>
    <message>
        <location filename="../rig/RigSession.cpp" line="255"/>
        <source>Cannot record to %1</source>
        <translation>無法錄製到 %1</translation>
    </message>
    <message>
        <location filename="../rig/RigSession.cpp" line="317"/>
        <source>Nothing recorded (no pose seen).</source>
        <translation>沒有錄得任何內容（未見位姿）。</translation>
    </message>
    <message>
        <location filename="../rig/RigSession.cpp" line="325"/>
        <source>The rig recording could not be saved: %1 (the take so far is in %2)</source>
        <translation>無法儲存實驗台錄製：%1（目前錄得的內容在 %2）</translation>
    </message>
    <message>
        <location filename="../rig/RigSession.cpp" line="354"/>
        <source>A trial is running.</source>
        <translation>試驗正在進行。</translation>
    </message>
    <message>
        <location filename="../rig/RigSession.cpp" line="360"/>
        <source>The latency is being measured already.</source>
        <translation>已在量度延遲。</translation>
    </message>
    <message>
        <location filename="../rig/RigSession.cpp" line="373"/>
        <source>cancelled</source>
        <translation>已取消</translation>
    </message>
    <message>
        <location filename="../rig/RigSessionTrials.cpp" line="468"/>
        <source>Trial %1: parked %2 cm from the lot, heading off by %3°</source>
        <translation>第 %1 次試驗：停在距泊車位 %2 厘米處，航向偏差 %3°</translation>
    </message>
    <message>
        <location filename="../rig/RigSessionTrials.cpp" line="473"/>
        <source>Trial %1 ended without a pose</source>
        <translation>第 %1 次試驗結束時沒有位姿</translation>
    </message>
    <message>
        <location filename="../rig/RigSessionTrials.cpp" line="477"/>
        <source> after running out %1 s in neutral</source>
        <extracomment>The car still moved when the trial&apos;s time was up and rolled on in neutral.</extracomment>
        <translation>（油門回中後滑行 %1 秒）</translation>
    </message>
    <message>
        <location filename="../rig/RigSessionTrials.cpp" line="481"/>
        <source> (stopped after %1 s)</source>
        <translation>（%1 秒後停止）</translation>
    </message>
    <message>
        <location filename="../rig/RigSessionTrials.cpp" line="484"/>
        <source> (failsafe after %1 s)</source>
        <translation>（%1 秒後進入失效保護）</translation>
    </message>
    <message>
        <location filename="../rig/RigSessionTrials.cpp" line="485"/>
        <source> (failsafe after %1 s: %2)</source>
        <translation>（%1 秒後失效保護：%2）</translation>
    </message>
    <message>
        <location filename="../rig/RigSessionTrials.cpp" line="491"/>
        <source>%1; %2</source>
        <extracomment>A rig trial&apos;s result, then what the method says of it (which law drove, and why).</extracomment>
        <translation>%1；%2</translation>
    </message>
</context>
</TS>
