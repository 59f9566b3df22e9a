namespace OperatorPanel.Simulator.Hosting;

/// <summary>How the simulated STL stations load their program, and so when their ports speak PPI (docs/ppi.md section 11).</summary>
public enum PpiMode
{
    /// <summary>The generated handler runs; the port speaks PPI whenever the handler does not hold it in Freeport (STOP, TERM).</summary>
    BesideHandler,

    /// <summary>No handler: the CPU runs an empty program and its port speaks PPI all the time (`opanel simulate --ppi`).</summary>
    WithoutHandler,
}
