using OperatorPanel.Simulator.Stl.Execution;

namespace OperatorPanel.Simulator.Stl.Operations;

/// <summary>What an instruction does to the machine; the compiled <see cref="StlOp"/> carries its resolved operands.</summary>
internal delegate void StlHandler(StlMachine machine, StlOp op);

/// <summary>What a box instruction does without power flow, returning its time in ns.</summary>
internal delegate long StlUnpoweredHandler(StlMachine machine, StlOp op);

/// <summary>
/// One row of the simulator's instruction table (<see cref="StlOperations"/>): the STL mnemonic, the op code the loader
/// links by, the execution time and the handler. A row cannot be written without a time and a handler.
/// </summary>
internal sealed record StlOperation(string Mnemonic, StlOpCode Code, StlExecutionTime Time, StlPowerFlow Flow, StlHandler Execute)
{
    /// <summary>A box instruction that does more than set ENO = 0 without power flow (FOR skips its loop).</summary>
    public StlUnpoweredHandler? Unpowered { get; init; }

    /// <summary>
    /// Why the instruction does nothing in the simulator (HSC, PLS: hardware it does not model); the loader warns with
    /// it by line, or refuses the instruction in strict mode. Null for an instruction the simulator executes.
    /// </summary>
    public string? NotSimulated { get; init; }
}
