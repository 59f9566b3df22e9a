namespace OperatorPanel.Core.Ppi;

/// <summary>
/// How <see cref="PpiMaster"/> talks (docs/ppi.md section 9). Times that depend on the line are counted in
/// characters of <see cref="CharacterTime"/> (11 bits: start, 8 data, even parity, stop; ML801761 p. 228).
/// </summary>
public sealed record PpiMasterOptions
{
    /// <summary>The panel's own PPI address: 0, the address of a PC running Micro/WIN (ML1409368 p. 159).</summary>
    public byte MasterAddress { get; init; }

    /// <summary>One character at the line's baud: 11 bits at 9600 baud = 1.146 ms.</summary>
    public TimeSpan CharacterTime { get; init; } = TimeSpan.FromTicks(TimeSpan.TicksPerSecond * 11 / 9600);

    /// <summary>
    /// How long the station may take to begin its answer after our frame left (its acknowledge, or its answer to a
    /// poll). No S7-200 figure is published (unconfirmed); 100 ms is generous next to libnodave's 140 ms read time-out
    /// for the whole exchange.
    /// </summary>
    public TimeSpan ReplyTimeout { get; init; } = TimeSpan.FromMilliseconds(100);

    /// <summary>
    /// How long the polls may go on before the answer must be there. The CPU prepares it in the communication phase of
    /// its next scan (C233-01 p. 4-23), so this bounds the scan time we wait out; the S7-200's scan watchdog is 500 ms.
    /// </summary>
    public TimeSpan AnswerTimeout { get; init; } = TimeSpan.FromMilliseconds(1000);

    /// <summary>
    /// Repeats of a read or set-up job without acknowledge, and of any poll without a sound answer (libnodave sends up
    /// to 3 times). A write job is sent once whatever this says (<see cref="PpiMaster.WriteAsync"/>).
    /// </summary>
    public int Retries { get; init; } = 2;

    /// <summary>
    /// Pause after a poll answered "no data yet" (16#E5) before the next poll. Zero polls at once, as libnodave does; at
    /// 187.5 kbaud a pause spares the CPU's port a flood of polls during a long scan.
    /// </summary>
    public TimeSpan PollPause { get; init; } = TimeSpan.Zero;

    /// <summary>
    /// The PDU reference of the master's first job. A random one for each link (each `opanel` run, each connect of the
    /// app), because a CPU keeps an answer until it is polled: an answer left by a run that ended mid-exchange would
    /// carry the new run's first reference if every run started at 1, and be taken for the new job's (docs/ppi.md 5.1).
    /// </summary>
    public ushort FirstReference { get; init; } = (ushort)Random.Shared.Next(1, ushort.MaxValue + 1);

    public static PpiMasterOptions ForBaud(int baud) =>
        new() { CharacterTime = TimeSpan.FromTicks(TimeSpan.TicksPerSecond * 11 / baud) };

    /// <summary>Time <paramref name="characters"/> take on the line.</summary>
    public TimeSpan Characters(int characters) => CharacterTime * characters;
}
